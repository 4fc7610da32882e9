:- module(geometry_clp,
          [ spatial_literal/2,        % +Case, +Literal
            spatial_literal/1,        % +Literal
            pose_geometry/5,          % +Case, +Tool, +Target, +Facts, -Geometry
            spatial_holds/4,          % +Case, +Literal, +Pose, +Geometry
            pose_constraints/5,       % +Case, +Required, +Negated, +Context, -Pose
            pose_search/2,            % +Pose, -Ground
            solve_pose/5,             % +Case, +Required, +Negated, +Context, -Result
            pose_reachable/5,         % +Case, +Tool, +Required, +Context, -Result
            size_constraints/5,       % +Case, +Kind, +Literals, +Context, -Dims
            size_search/3,            % +Case, +Dims, -Ground
            solve_size/5              % +Case, +Kind, +Literals, +Context, -Result
          ]).

/** <module> CLP(R)/CLP(FD) models: qualitative literals to numbers

Two models, each split like library(clpfd) into a *core relation* that posts
constraints and a *search* that picks values:

  - **Pose**: spatial literals (behind/2, hook_down/1, near/2, ...) to the pose numbers
    of a tool relative to its target, hook_pose(Dx, Dy, Roll) or wedge_pose(R, Gap,
    Yaw) (metres, radians; see ontology/spatial.pl).  pose_constraints/5 posts,
    pose_search/2 labels, solve_pose/5 does both and names a minimal conflict when
    there is no pose.
  - **Size**: structural literals (handle_length(T, long), shape(W, box), ...) to the
    dimensions of a new tool, named as the fields of HookSpec / BlockSpec
    (creative_py/mesh/spec.py).  size_constraints/5 posts, size_search/3 labels,
    solve_size/5 does both.

The definitions are data of the case's namespace (its module, its kind's, the shared
one: knowledge.pl), asked through these hook predicates (case.pl says how a missing
one is reported):

  - spatial_definition(?Case, ?Literal, ?PoseTerm, ?Constraints): Literal (its
    arguments the roles tool, target, context) holds when every linear comparison of
    Constraints holds for the numbers of PoseTerm; several clauses are alternatives.
    Right-hand sides may name geometry parameters.
  - pose_domain(?Case, ?PoseTerm, ?Constraints): where a pose can be at all, posted
    under every query (never named in a conflict).
  - geometry_default(?Case, ?Name, ?Value, ?Meaning): the geometry parameters, in the
    order they are computed, with the values used when the state does not give them.
  - geometry_value(?Case, ?Name, ?Tool, ?Target, +Geometry, -Value), proved on the
    state (case:case_prove/2), optional: the parameter Name from the facts; Geometry
    holds the parameters listed before it.
  - reach_definition(?Case, ?PoseTerm, ?Constraints): how far a held tool reaches:
    every pose the arm can put it at satisfies the linear comparisons Constraints
    (over the pose numbers and geometry parameters, which may come from the tool's
    catalogue facts); several clauses are alternatives; [] when the case's geometry
    sets no reach (pose_reachable/5 then answers undecided).  Read only by
    pose_reachable/5, never by the experiments.
  - task_roles/3 (case.pl), task_predicate/2 (abstract_state.pl): the default target,
    and the task literals a size query ignores.

and for the size model, keyed by the kind of the new tool (ontology/kinds/) and read
in the namespace of the case the tool is for (case:case_knowledge/2):

  - qualitative_range(?Property, ?Value, ?Low, ?High, ?Bounds) (ontology/ranges.pl);
  - size_field(?Kind, ?Field, ?Property): a number field and the property it carries;
  - size_choice(?Kind, ?Field, ?Property, ?Values): a symbolic field, its values in
    the order tried; size_choice_constraint(?Field, ?Value, ?Constraints) what a value
    adds (a cylinder: width =:= length; a prism: its blunted tip_height between
    min_tip_height_m and its height), posted when a literal fixes the value or the
    search picks it, with the context's size parameters;
  - size_fixed(?Kind, ?Field, ?Value): a field the kind does not size;
  - size_integer_field(?Field): a field in whole units (CLP(FD));
  - size_ratio(?Kind, ?Property, ?Numerator, ?Denominator): a property that bounds a
    ratio of two fields;
  - size_constraint(?Kind, ?ContextFact, ?Constraints): what a fact of the sizing
    context asks of a new tool of Kind, linear comparisons over field names,
    size_parameter/3 names and the fact's numbers;
  - size_parameter(?Name, ?Value, ?Meaning): a margin, overridden by a context fact
    Name(Value);
  - subclass_of(?Class, ?Super) and structural_predicate(?Class, ?Name/1): a class
    literal C(T) agrees with the kinds that are C or below it.

Metres are CLP(R) variables; angles in whole degrees are CLP(FD) integers.

**Search.** Each variable in turn, in the order of the pose or dims term, is bound to
the midpoint of its current interval (clpr inf/2 and sup/2, clpfd fd_inf/2 and
fd_sup/2), rounded to 0.1 mm (0.0001 rad) when that stays strictly inside.  Earlier
choices narrow later intervals, so the point is inside the feasible region, never on a
bound unless the region is a single point.

**Negation.** A literal that must not hold requires the complement of its definition.
A definition with several clauses (hook_flat/1: Roll >= 1.2 or Roll =< -1.2) is a
disjunction, so its complement is the conjunction of the clauses' complements; the
complement of one clause (a conjunction) is a disjunction: one of its comparisons is
violated.  pose_constraints/5 enumerates these choices on backtracking, comparisons in
the order the definition lists them; solve_pose/5 takes the first choice that is
feasible.  The ontology lists first the side that is meaningful (not behind: Dx below
the minimum, i.e. the prong in front of or beside the cube).

**Conflicts.** When there is no solution, the conflict set is found by deletion: drop
each literal (and, for sizes, each context fact) in turn, keeping it out while the rest
is still infeasible.  The remainder is minimal: removing any one of its members makes
the problem feasible.  The pose domain and the property domains (union of the
qualitative ranges) are always posted and never named.
*/

:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(clpr)).
:- use_module(library(clpfd), [ (#>=)/2, (#=<)/2, (#>)/2, (#<)/2, (#=)/2,
                                fd_inf/2, fd_sup/2, op(_, _, _) ]).
:- use_module(knowledge).
:- use_module(case).

                 /*******************************
                 *     SPATIAL DEFINITIONS      *
                 *******************************/

%!  spatial_literal(+Case, +Literal) is semidet.
%
%   Literal is a spatial literal of Case: the case's ontology defines it over the
%   case's pose numbers (spatial_definition/4).
%
%   ==
%   ?- spatial_literal(hook, behind(hook_a2, cube1)).
%   true.
%   ==
spatial_literal(Case, Literal) :-
    must_be_case(Case),
    must_be(callable, Literal),
    functor(Literal, N, A),
    functor(Template, N, A),
    once(case_holds(spatial_definition(Case, Template, _, _))).

%!  spatial_literal(+Literal) is semidet.
%
%   Literal is a spatial literal of some case.
%
%   ==
%   ?- spatial_literal(near(wedge_a2, door1)).
%   true.
%   ==
spatial_literal(Literal) :-
    callable(Literal),
    functor(Literal, N, A),
    functor(Template, N, A),
    once(ontology_holds(spatial_definition(_, Template, _, _))).

%!  pose_geometry(+Case, +Tool, +Target, +Facts:list, -Geometry:list) is det.
%
%   Geometry lists Name=Value for every geometry parameter of Case
%   (geometry_default/4), in the order the case lists them, each taken from the
%   primitive facts Facts by the case's geometry_value/6 rule where it has one that
%   succeeds, else the default.  Tool and Target may be unbound (then only facts naming
%   no tool or target are used).
%
%   Hook: cube_half from size(Target, Sx, _, _); prong_half from hook_width_m(Tool, W)
%   (a stick: handle_width_m); handle_half from handle_width_m(Tool, W);
%   tube_length from tube_length_m/2; dx_min, dx_max, dy_min, dy_max from tube_mouth/4,
%   tube_length_m/2, tube_inner_m/3 and pose(Target, ...): the prong stays inside the
%   tube.  Wedge: door_width from door_width_m(Target, W); door_angle from
%   door_angle(Target, A); wedge_half from size(Tool, Sx, _, _) or block_length_m/2.
%
%   ==
%   ?- pose_geometry(hook, h, cube1, [size(cube1, 0.04, 0.04, 0.04)], G),
%      memberchk(cube_half=C, G).
%   C = 0.02.
%   ==
pose_geometry(Case, Tool, Target, Facts, Geometry) :-
    must_be(list, Facts),
    findall(Name-Default,
            case_holds(geometry_default(Case, Name, Default, _)),
            Defaults),
    (   case_has_hook(Case, geometry_value/6)
    ->  Rules = true
    ;   Rules = false
    ),
    foldl(geometry_param_(Rules, Case, Tool, Target, Facts), Defaults, [], Reversed),
    reverse(Reversed, Geometry).

%   geometry_param_(+Rules, +Case, +Tool, +Target, +Facts, +Name-Default, +G0, -G): G0
%   holds the parameters computed so far, last first.
geometry_param_(Rules, Case, Tool, Target, Facts, Name-Default, G0, [Name=Value|G0]) :-
    reverse(G0, Before),
    (   Rules == true,
        findall(V, once(case_prove(geometry_value(Case, Name, Tool, Target, Before, V),
                                   Facts)),
                [V1])
    ->  Value = V1
    ;   Value = Default
    ).

%!  spatial_holds(+Case, +Literal, +Pose, +Geometry) is semidet.
%
%   The spatial Literal holds for the ground pose term Pose (hook_pose/3 or
%   wedge_pose/3) in the task geometry Geometry (from pose_geometry/5): the numbers
%   satisfy every comparison of one clause of its definition.
%
%   ==
%   ?- pose_geometry(hook, _, _, [], G),
%      spatial_holds(hook, behind(h, cube1), hook_pose(0.04, 0.0, 0.0), G).
%   true.
%   ==
spatial_holds(Case, Literal, Pose, Geometry) :-
    must_be(ground, Pose),
    definition_clauses_(Case, Literal, Pose, Clauses),
    member(Comparisons, Clauses),
    maplist(holds_(Geometry), Comparisons),
    !.

holds_(Geometry, Comparison) :-
    instantiate_(Comparison, Geometry, C),
    call(C).

%   definition_clauses_(+Case, +Literal, ?Pose, -Clauses): the constraint lists of
%   Literal's definition, sharing Pose's variables.
definition_clauses_(Case, Literal, Pose, Clauses) :-
    must_be(callable, Literal),
    functor(Literal, N, A),
    functor(Template, N, A),
    findall(Pose-Cs, case_holds(spatial_definition(Case, Template, Pose, Cs)), Pairs),
    (   Pairs == []
    ->  domain_error(spatial_literal(Case), Literal)
    ;   maplist(pose_clause_(Pose), Pairs, Clauses)
    ).

pose_clause_(Pose, Pose-Cs, Cs).

%   instantiate_(+Comparison, +Env, -Numeric): parameter names replaced by their
%   values, ground subexpressions evaluated.  Env is a pose geometry (a list
%   Name=Value) or size(Dims, Context) (field names to their variables, then size
%   parameters).
instantiate_(Comparison, Env, Numeric) :-
    Comparison =.. [Op, L0, R0],
    comparison_(Op),
    !,
    expr_(L0, Env, L),
    expr_(R0, Env, R),
    Numeric =.. [Op, L, R].
instantiate_(Comparison, _, _) :-
    domain_error(linear_comparison, Comparison).

comparison_(>=).
comparison_(=<).
comparison_(>).
comparison_(<).
comparison_(=:=).

expr_(V, _, V) :-
    var(V),
    !.
expr_(N, _, N) :-
    number(N),
    !.
expr_(A, Env, V) :-
    atom(A),
    !,
    env_value_(Env, A, V).
expr_(E0, Env, E) :-
    compound(E0),
    E0 =.. [F|Args0],
    exprs_(Args0, Env, Args),
    E1 =.. [F|Args],
    (   ground(E1)
    ->  E is E1
    ;   E = E1
    ).

exprs_([], _, []).
exprs_([E0|Es0], Env, [E|Es]) :-
    expr_(E0, Env, E),
    exprs_(Es0, Env, Es).

env_value_(size(Case, Dims, Context), A, V) :-
    !,
    (   memberchk(A=V0, Dims)
    ->  V = V0
    ;   A == pi
    ->  V is pi
    ;   size_parameter_(Case, A, Context, V)
    ).
env_value_(Geometry, A, V) :-
    (   memberchk(A=V0, Geometry)
    ->  V = V0
    ;   A == pi
    ->  V is pi
    ;   existence_error(geometry_parameter, A)
    ).

negate_(>=, <).
negate_(=<, >).
negate_(>, =<).
negate_(<, >=).

                 /*******************************
                 *           POSE MODEL         *
                 *******************************/

%!  pose_constraints(+Case, +Required:list, +Negated:list, +Context:list, -Pose) is nondet.
%
%   Pose is hook_pose(Dx, Dy, Roll) or wedge_pose(R, Gap, Yaw) with CLP(R) constraints
%   saying: every literal of Required holds, no literal of Negated holds, and the pose
%   lies in the case's pose domain.  Context is a list of primitive facts giving the
%   task geometry (see pose_geometry/5); the tool and target are the objects the
%   literals name (else the case's task_roles/3).  Solutions differ in the disjunct
%   chosen for disjunctive definitions and complements (see the module header); fails
%   if none is feasible.
%
%   @error domain_error(spatial_literal(Case), L) for a literal with no definition.
%
%   ==
%   ?- use_module(library(clpr)),
%      pose_constraints(hook, [behind(h, cube1)], [], [], P), P = hook_pose(Dx, _, _),
%      inf(Dx, I).
%   I = 0.025.
%   ==
pose_constraints(Case, Required, Negated, Context, Pose) :-
    must_be_case(Case),
    must_be(list, Required),
    must_be(list, Negated),
    must_be(list, Context),
    append(Required, Negated, All),
    roles_(Case, All, Tool, Target),
    pose_geometry(Case, Tool, Target, Context, Geometry),
    case_answer(pose_domain(Case, Pose, Domain)),
    post_all_(Domain, Geometry),
    maplist(post_required_(Case, Pose, Geometry), Required),
    maplist(post_negated_(Case, Pose, Geometry), Negated).

roles_(Case, Literals, Tool, Target) :-
    case_roles(Case, Target0, _),
    (   member(L, Literals),
        literal_role_(Case, L, tool, Tool0)
    ->  Tool = Tool0
    ;   true
    ),
    (   member(L, Literals),
        literal_role_(Case, L, target, T1)
    ->  Target = T1
    ;   Target = Target0
    ).

literal_role_(Case, Literal, Role, Object) :-
    compound(Literal),
    functor(Literal, N, A),
    functor(Template, N, A),
    once(case_holds(spatial_definition(Case, Template, _, _))),
    arg(I, Template, Role),
    arg(I, Literal, Object),
    nonvar(Object).

post_all_(Comparisons, Geometry) :-
    maplist(post_(Geometry), Comparisons).

post_(Geometry, Comparison) :-
    instantiate_(Comparison, Geometry, C),
    {C}.

post_required_(Case, Pose, Geometry, Literal) :-
    definition_clauses_(Case, Literal, Pose, Clauses),
    member(Comparisons, Clauses),
    post_all_(Comparisons, Geometry).

post_negated_(Case, Pose, Geometry, Literal) :-
    definition_clauses_(Case, Literal, Pose, Clauses),
    maplist(post_violated_(Geometry), Clauses).

post_violated_(Geometry, Comparisons) :-
    member(Comparison, Comparisons),
    Comparison =.. [Op, L, R],
    negate_(Op, NOp),
    Violated =.. [NOp, L, R],
    post_(Geometry, Violated).

%!  pose_search(+Pose, -Ground) is semidet.
%
%   Ground is Pose with each variable, in argument order, bound to the midpoint of its
%   interval under the posted constraints.  Fails if a variable is unbounded.
%
%   ==
%   ?- use_module(library(clpr)),
%      {X >= 0.025, X =< 0.07}, pose_search(hook_pose(X, 0.0, 0.0), G).
%   G = hook_pose(0.0475, 0.0, 0.0).
%   ==
pose_search(Pose, Ground) :-
    must_be(compound, Pose),
    Pose =.. [_|Vars],
    maplist(label_midpoint_, Vars),
    Ground = Pose.

label_midpoint_(V) :-
    (   var(V)
    ->  inf(V, Inf),
        sup(V, Sup),
        midpoint_(Inf, Sup, M),
        {V =:= M}
    ;   true
    ).

midpoint_(Inf, Sup, M) :-
    M0 is (Inf + Sup) / 2,
    Rounded is round(M0 * 10000) / 10000,
    (   Rounded > Inf,
        Rounded < Sup
    ->  M = Rounded
    ;   M = M0
    ).

%!  solve_pose(+Case, +Required:list, +Negated:list, +Context:list, -Result) is det.
%
%   Result is pose(Ground), a ground pose term inside the region pose_constraints/5
%   describes (its first feasible disjunct), or infeasible(Conflict) where Conflict is a
%   minimal list of the literals that cannot hold together (a negated literal L appears
%   as not(L)); infeasible([]) when the context's pose domain is empty by itself.
%
%   ==
%   ?- solve_pose(hook, [behind(h, cube1), hook_down(h)], [], [], R).
%   R = pose(hook_pose(0.0475, 0.0, 0.0)).
%   ?- solve_pose(hook, [behind(h, cube1), in_front(h, cube1)], [hook_flat(h)], [], R).
%   R = infeasible([behind(h, cube1), in_front(h, cube1)]).
%   ==
solve_pose(Case, Required, Negated, Context, Result) :-
    must_be(list, Required),
    must_be(list, Negated),
    (   pose_point_(Case, Required, Negated, Context, Ground)
    ->  Result = pose(Ground)
    ;   findall(req(L), member(L, Required), Rs),
        findall(neg(L), member(L, Negated), Ns),
        append(Rs, Ns, Items),
        minimal_conflict_(Items, pose_items_feasible_(Case, Context), Conflict0),
        maplist(item_literal_, Conflict0, Conflict),
        Result = infeasible(Conflict)
    ).

pose_point_(Case, Required, Negated, Context, Ground) :-
    findall(G,
            once(( pose_constraints(Case, Required, Negated, Context, Pose),
                   pose_search(Pose, G) )),
            [Ground]).

pose_items_feasible_(Case, Context, Items) :-
    findall(L, member(req(L), Items), Rs),
    findall(L, member(neg(L), Items), Ns),
    \+ \+ pose_point_(Case, Rs, Ns, Context, _).

item_literal_(req(L), L).
item_literal_(neg(L), not(L)).
item_literal_(ctx(F), F).

%   minimal_conflict_(+Items, :Feasible, -Conflict): deletion filter.  Items is
%   infeasible; Conflict is an irreducible infeasible sublist.
minimal_conflict_(Items, Feasible, Conflict) :-
    deletion_(Items, [], Feasible, Conflict).

deletion_([], Kept, _, Conflict) :-
    reverse(Kept, Conflict).
deletion_([I|Is], Kept, Feasible, Conflict) :-
    reverse(Kept, KeptInOrder),
    append(KeptInOrder, Is, Without),
    (   call(Feasible, Without)
    ->  deletion_(Is, [I|Kept], Feasible, Conflict)
    ;   deletion_(Is, Kept, Feasible, Conflict)
    ).

%!  pose_reachable(+Case, +Tool, +Required:list, +Context:list, -Result) is det.
%
%   Whether the held Tool can be put at a pose where every spatial literal of Required
%   holds, in the task described by the primitive facts Context (the catalogue's
%   numbers of Tool, the perceived apparatus and target): the pose model of
%   pose_constraints/5 plus the case's reach_definition/3, whose geometry parameters
%   pose_geometry/5 computes with Tool's own dimensions.  Result is
%
%     - reachable(Pose): a ground pose within reach where Required holds;
%     - unreachable(Conflict, Params): no such pose; Conflict is a minimal sublist of
%       Required that cannot hold within reach (the reach and the pose domain are
%       always posted, never named), Params lists param(Name, Value, Meaning) for the
%       geometry parameters the reach definition names;
%     - undecided: the case's reach definition is [] (its geometry sets no reach, the
%       outcome depends on something else, a force), so the pose model cannot tell.
%
%   Tool creation asks this before it tries the learned model's best tool in a harder
%   task: an unreachable pose is a failure the geometry predicts, so no trial is run.
%
%   ==
%   ?- pose_reachable(hook, h, [behind(h, cube1)],
%                     [handle_length_m(h, 0.2), tube_mouth(tube1, 0.6, 0.0, 0.0),
%                      tube_length_m(tube1, 0.45), tube_inner_m(tube1, 0.1, 0.06),
%                      pose(cube1, 1.0, 0.0, 0.0, 0.0)], R).
%   R = unreachable([behind(h, cube1)], [param(dx_reach, ..., ...)]).
%   ==
pose_reachable(Case, Tool, Required, Context, Result) :-
    must_be_case(Case),
    must_be(atom, Tool),
    must_be(list, Required),
    must_be(list, Context),
    findall(Cs, case_holds(reach_definition(Case, _, Cs)), Reaches),
    (   forall(member(Cs, Reaches), Cs == [])
    ->  Result = undecided
    ;   roles_(Case, Required, _, Target),
        (   reach_point_(Case, Tool, Target, Required, Context, Ground)
        ->  Result = reachable(Ground)
        ;   findall(req(L), member(L, Required), Items),
            minimal_conflict_(Items, reach_items_feasible_(Case, Tool, Target, Context),
                              Conflict0),
            maplist(item_literal_, Conflict0, Conflict),
            pose_geometry(Case, Tool, Target, Context, Geometry),
            findall(param(N, V, M),
                    ( member(Cs, Reaches),
                      reach_parameter_(Cs, N),
                      memberchk(N=V, Geometry),
                      once(case_holds(geometry_default(Case, N, _, M))) ),
                    Params0),
            list_to_set(Params0, Params),
            Result = unreachable(Conflict, Params)
        )
    ).

reach_point_(Case, Tool, Target, Required, Context, Ground) :-
    findall(G,
            once(( reach_constraints_(Case, Tool, Target, Required, Context, Pose),
                   pose_search(Pose, G) )),
            [Ground]).

reach_constraints_(Case, Tool, Target, Required, Context, Pose) :-
    pose_geometry(Case, Tool, Target, Context, Geometry),
    case_answer(pose_domain(Case, Pose, Domain)),
    post_all_(Domain, Geometry),
    maplist(post_required_(Case, Pose, Geometry), Required),
    case_holds(reach_definition(Case, Pose, Reach)),
    post_all_(Reach, Geometry).

reach_items_feasible_(Case, Tool, Target, Context, Items) :-
    findall(L, member(req(L), Items), Rs),
    \+ \+ reach_point_(Case, Tool, Target, Rs, Context, _).

%   reach_parameter_(+Comparisons, -Name): a geometry parameter Comparisons names.
reach_parameter_(Comparisons, Name) :-
    member(C, Comparisons),
    C =.. [_, L, R],
    member(Side, [L, R]),
    sub_term(Name, Side),
    atom(Name),
    Name \== pi.

                 /*******************************
                 *           SIZE MODEL         *
                 *******************************/

%!  size_constraints(+Case, +Kind, +Literals:list, +Context:list, -Dims:list) is semidet.
%
%   Dims lists Field=Value for the spec fields of a new tool of Kind (a kind with
%   size_field/3 facts in the namespace of Case: hook, stick, block) for the task of
%   Case, Value a constrained variable or a fixed
%   value, such that the structural Literals hold and the tool suits the task Context.
%   Fails if they cannot.  Dims holds the number fields (size_field/3), then the
%   symbolic ones (size_choice/4, unbound if no literal fixes them), then the fixed
%   ones (size_fixed/3), each in the ontology's order.
%
%   Fields: hook: handle_length, handle_width, hook_length, hook_width (CLP(R), metres),
%   hook_angle_deg (CLP(FD), whole degrees), hook_side (left or right).  stick:
%   handle_length, handle_width; hook_length = 0.0, hook_width = 0.0, hook_side = none,
%   hook_angle_deg = 90.  block: length, width, height, tip_height (metres: a prism's
%   blunted tip, 0 for a box or a cylinder), shape.
%
%   Structural literals: those of the ontology (handle_length(T, long), hook_side(T,
%   left), shape(W, box), mechanical_advantage(W, above_one), ...); class literals
%   (unary structural literals: tool/1, hook_like/1, hook/1, stick/1, object/1, block/1)
%   must agree with Kind (Kind is the class or below it); spatial and task literals are
%   ignored.  Context facts are posted by the size_constraint/3 facts for Kind of the
%   case's namespace (its own file, its kind's, the shared files; others are ignored),
%   so that one case's constraints never size another case's tools, for example:
%
%     - tube_length_m(Tube, L): handle_length >= L + reach_margin_m (0.05 m unless a
%       reach_margin_m(M) fact says otherwise), so that the prong reaches behind a cube
%       at the tube's far end with the gripper outside.
%     - tube_inner_m(Tube, W, H): handle_width + hook_length =< min(W, H) -
%       tube_clearance_m (0.005 m): the tool turns inside the tube.
%     - max_tool_length(M): handle_length =< M (block: length and width =< M).
%     - door_gap_m(Door, G): height > G (the wedge must reach under the door) and
%       tip_height < G (its blunted tip slides under it).
%     - min_wall_m(M): every solid dimension >= M (printable).
%
%   A literal of a property that Kind does not have (hook_length/2 for a block) makes
%   the spec infeasible.
%
%   @error domain_error(oneof(Kinds), Kind) for a kind without size fields.
%   @error domain_error(structural_literal(Kind), L) for an unknown literal or value.
%
%   ==
%   ?- use_module(library(clpr)),
%      size_constraints(hook, hook, [handle_length(t, long)], [tube_length_m(tube1, 0.45)], D),
%      memberchk(handle_length=L, D), inf(L, I).
%   I = 0.5.
%   ==
size_constraints(Case, Kind, Literals, Context, Dims) :-
    must_be_size_kind_(Case, Kind),
    must_be(list, Literals),
    must_be(list, Context),
    size_items_(Case, Kind, Literals, Context, Items),
    size_model_(Case, Kind, Context, Items, Dims).

must_be_size_kind_(Case, Kind) :-
    must_be(atom, Kind),
    (   case_knowledge(Case, size_field(Kind, _, _))
    ->  true
    ;   findall(K, case_knowledge(Case, size_field(K, _, _)), Ks0),
        list_to_set(Ks0, Ks),
        domain_error(oneof(Ks), Kind)
    ).

size_items_(Case, Kind, Literals, Context, Items) :-
    foldl(literal_item_(Case, Kind), Literals, Items, Items1),
    findall(ctx(F), ( member(F, Context), context_item_(Case, Kind, F) ), Items1).

literal_item_(Case, Kind, L, Items0, Items) :-
    must_be(callable, L),
    (   ignored_literal_(Case, L)
    ->  Items0 = Items
    ;   check_structural_(Case, Kind, L),
        Items0 = [lit(L)|Items]
    ).

ignored_literal_(Case, L) :-
    (   spatial_literal(L)
    ;   functor(L, N, A),
        case_holds(task_predicate(Case, N/A))
    ),
    !.

check_structural_(Case, Kind, L) :-
    (   class_literal_(Case, L, _)
    ->  true
    ;   L =.. [P, _, V],
        property_field_(Case, P),
        nonvar(V),
        (   case_knowledge(Case, qualitative_range(P, V, _, _, _))
        ;   case_knowledge(Case, size_choice(_, _, P, Vs)),
            memberchk(V, Vs)
        )
    ->  true
    ;   L =.. [P, _, V],
        case_knowledge(Case, size_ratio(_, P, _, _)),
        nonvar(V),
        case_knowledge(Case, qualitative_range(P, V, _, _, _))
    ->  true
    ;   domain_error(structural_literal(Kind), L)
    ).

%   class_literal_(+Case, +L, -Kinds): L is a class literal C(T) (a unary structural
%   literal); Kinds are the size kinds that are C or below it in the hierarchy.
class_literal_(Case, L, Kinds) :-
    compound(L),
    compound_name_arity(L, C, 1),
    once(case_knowledge(Case, structural_predicate(_, C/1))),
    findall(K, ( size_kind_(Case, K), is_a_(Case, K, C) ), Kinds).

size_kind_(Case, Kind) :-
    findall(K, case_knowledge(Case, size_field(K, _, _)), Ks),
    list_to_set(Ks, Kinds),
    member(Kind, Kinds).

%   is_a_(+Case, +Class, +Super): Class is Super or below it.
is_a_(_, C, C) :- !.
is_a_(Case, C, Super) :-
    case_knowledge(Case, subclass_of(C, C1)),
    is_a_(Case, C1, Super),
    !.

%   P is a property some kind of tool has a spec field for.
property_field_(Case, P) :-
    (   case_knowledge(Case, size_field(_, _, P))
    ;   case_knowledge(Case, size_choice(_, _, P, _))
    ),
    !.

context_item_(Case, Kind, F) :-
    once(case_knowledge(Case, size_constraint(Kind, F, _))).

%   size_model_(+Case, +Kind, +Context, +Items, -Dims): post the property domains and every item.
size_model_(Case, Kind, Context, Items, Dims) :-
    findall(F-P, case_knowledge(Case, size_field(Kind, F, P)), FieldProps),
    maplist(field_var_, FieldProps, NumDims),
    findall(F=_, case_knowledge(Case, size_choice(Kind, F, _, _)), ChoiceDims),
    findall(F=V, case_knowledge(Case, size_fixed(Kind, F, V)), Fixed),
    append([NumDims, ChoiceDims, Fixed], Dims),
    maplist(post_domain_(Case, FieldProps, Dims), FieldProps),
    maplist(post_size_item_(Case, Kind, Context, Dims), Items),
    bound_choice_constraints_(Case, Dims, Context).

%   bound_choice_constraints_(+Case, +Dims, +Context): the constraints of every symbolic field a
%   literal has fixed (shape(W, triangular_prism): its blunted tip).
bound_choice_constraints_(Case, Dims, Context) :-
    include(bound_choice_(Case), Dims, Bound),
    maplist(bound_choice_constraint_(Case, Dims, Context), Bound).

bound_choice_(Case, F=V) :-
    nonvar(V),
    once(case_knowledge(Case, size_choice(_, F, _, _))).

bound_choice_constraint_(Case, Dims, Context, F=V) :-
    choice_constraints_(Case, F, V, Dims, Context).

field_var_(F-_, F=_).

%   The domain of a field: the union of its property's qualitative ranges.
post_domain_(Case, _, Dims, F-P) :-
    memberchk(F=V, Dims),
    aggregate_all(min(Lo), case_knowledge(Case, qualitative_range(P, _, Lo, _, _)), Min),
    aggregate_all(max(Hi), case_knowledge(Case, qualitative_range(P, _, _, Hi, _)), Max),
    (   integer_field_(Case, F)
    ->  Lo1 is ceiling(Min),
        Hi1 is floor(Max),
        V #>= Lo1,
        V #=< Hi1
    ;   {V >= Min, V =< Max}
    ).

integer_field_(Case, F) :-
    case_knowledge(Case, size_integer_field(F)),
    !.

post_size_item_(Case, Kind, _, _, lit(L)) :-
    class_literal_(Case, L, Kinds),
    !,
    memberchk(Kind, Kinds).
post_size_item_(Case, Kind, _, Dims, lit(L)) :-
    L =.. [P, _, Value],
    case_knowledge(Case, size_choice(Kind, F, P, _)),
    !,
    memberchk(F=Value, Dims).
post_size_item_(Case, Kind, _, Dims, lit(L)) :-
    L =.. [P, _, Value],
    case_knowledge(Case, size_ratio(Kind, P, NumField, DenField)),
    !,
    case_knowledge(Case, qualitative_range(P, Value, Lo, Hi, Bounds)),
    memberchk(NumField=N, Dims),
    memberchk(DenField=D, Dims),
    range_constraint_(Bounds, N, Lo * D, Hi * D).
post_size_item_(Case, Kind, _, Dims, lit(L)) :-
    L =.. [P, _, Value],
    case_knowledge(Case, size_field(Kind, F, P)),
    !,
    memberchk(F=V, Dims),
    case_knowledge(Case, qualitative_range(P, Value, Lo, Hi, Bounds)),
    (   integer_field_(Case, F)
    ->  fd_range_constraint_(Bounds, V, Lo, Hi)
    ;   range_constraint_(Bounds, V, Lo, Hi)
    ).
post_size_item_(_, _, _, _, lit(_)) :-
    !,
    fail.
post_size_item_(Case, Kind, Context, Dims, ctx(F)) :-
    findall(Cs, case_knowledge(Case, size_constraint(Kind, F, Cs)), Css),
    append(Css, Comparisons),
    maplist(post_(size(Case, Dims, Context)), Comparisons).

size_parameter_(Case, Name, Context, Value) :-
    Fact =.. [Name, V],
    (   memberchk(Fact, Context)
    ->  Value = V
    ;   case_knowledge(Case, size_parameter(Name, Value, _))
    ->  true
    ;   existence_error(size_parameter, Name)
    ).

range_constraint_(closed_open, V, Lo, Hi) :-
    {V >= Lo, V < Hi}.
range_constraint_(closed_closed, V, Lo, Hi) :-
    {V >= Lo, V =< Hi}.
range_constraint_(open_closed, V, Lo, Hi) :-
    {V > Lo, V =< Hi}.

fd_range_constraint_(closed_open, V, Lo, Hi) :-
    Lo1 is ceiling(Lo),
    Hi1 is ceiling(Hi),
    V #>= Lo1,
    V #< Hi1.
fd_range_constraint_(closed_closed, V, Lo, Hi) :-
    Lo1 is ceiling(Lo),
    Hi1 is floor(Hi),
    V #>= Lo1,
    V #=< Hi1.
fd_range_constraint_(open_closed, V, Lo, Hi) :-
    Lo1 is floor(Lo),
    Hi1 is floor(Hi),
    V #> Lo1,
    V #=< Hi1.

%!  size_search(+Case, +Dims:list, -Ground:list) is nondet.
%
%   Ground is Dims with every value bound: a symbolic field (hook_side, shape) to the
%   first value of its size_choice/4 list that keeps the rest feasible (a cylinder gets
%   width = length), then each number, in Dims order, to the midpoint of its interval
%   (metres rounded to 0.1 mm when that stays strictly inside; degrees to a whole
%   number).  On backtracking, the next values of the symbolic fields.
%
%   ==
%   ?- size_constraints(wedge, block, [shape(w, triangular_prism), block_length(w, long)],
%                       [], D),
%      size_search(wedge, D, G).
%   G = [length=0.16, width=0.085, height=0.0475, tip_height=0.0024,
%        shape=triangular_prism].
%   ==
size_search(Case, Dims, Ground) :-
    size_search_(Case, Dims, [], Ground).

%   size_search_(+Case, +Dims, +Context, -Ground): size_search/3 where the constraints of a
%   symbolic value read their size parameters from Context (then the defaults).
size_search_(Case, Dims, Context, Ground) :-
    must_be(list, Dims),
    label_choices_(Case, Dims, Context),
    maplist(label_field_(Case), Dims),
    Ground = Dims.

label_choices_(Case, Dims, Context) :-
    findall(F-Vs, case_knowledge(Case, size_choice(_, F, _, Vs)), Choices),
    maplist(label_choice_(Case, Dims, Context), Choices).

label_choice_(Case, Dims, Context, F-Values) :-
    (   memberchk(F=V, Dims)
    ->  (   var(V)
        ->  member(V, Values)
        ;   true
        ),
        choice_constraints_(Case, F, V, Dims, Context)
    ;   true
    ).

%   The constraints a symbolic field's value adds (size_choice_constraint/3), their
%   size parameters from Context or the defaults.
choice_constraints_(Case, F, V, Dims, Context) :-
    findall(Cs, case_knowledge(Case, size_choice_constraint(F, V, Cs)), Css),
    append(Css, Comparisons),
    maplist(post_(size(Case, Dims, Context)), Comparisons).

label_field_(Case, F=V) :-
    (   var(V),
        integer_field_(Case, F)
    ->  fd_inf(V, Inf),
        fd_sup(V, Sup),
        M is (Inf + Sup) // 2,
        V #= M
    ;   var(V)
    ->  label_midpoint_(V)
    ;   true
    ).

%!  solve_size(+Case, +Kind, +Literals:list, +Context:list, -Result) is det.
%
%   Result is dims(Fields), Fields a ground list Field=Value (size_constraints/5,
%   size_search/3) for a new tool of Kind in the task of Case, or infeasible(Conflict), Conflict a minimal
%   list of the literals and context facts that cannot hold together.
%
%   ==
%   ?- solve_size(hook, hook, [hook(t), handle_length(t, long), hook_side(t, left)],
%                 [tube_length_m(tube1, 0.45), max_tool_length(0.70)], R).
%   R = dims([handle_length=0.6, handle_width=0.018, hook_length=0.03,
%             hook_width=0.012, hook_angle_deg=90, hook_side=left]).
%   ?- solve_size(hook, hook, [handle_length(t, long)], [max_tool_length(0.3)], R).
%   R = infeasible([handle_length(t, long), max_tool_length(0.3)]).
%   ==
solve_size(Case, Kind, Literals, Context, Result) :-
    must_be_size_kind_(Case, Kind),
    size_items_(Case, Kind, Literals, Context, Items),
    (   size_point_(Case, Kind, Context, Items, Ground)
    ->  Result = dims(Ground)
    ;   minimal_conflict_(Items, size_items_feasible_(Case, Kind, Context), Conflict0),
        maplist(size_item_term_, Conflict0, Conflict),
        Result = infeasible(Conflict)
    ).

size_point_(Case, Kind, Context, Items, Ground) :-
    findall(G,
            once(( size_model_(Case, Kind, Context, Items, Dims),
                   size_search_(Case, Dims, Context, G) )),
            [Ground]).

size_items_feasible_(Case, Kind, Context, Items) :-
    \+ \+ size_point_(Case, Kind, Context, Items, _).

size_item_term_(lit(L), L).
size_item_term_(ctx(F), F).
