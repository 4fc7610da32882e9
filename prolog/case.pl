:- module(case,
          [ must_be_case/1,           % +Case
            case_roles/3,             % +Case, -Target, -Context
            case_answer/1,            % +Hook
            case_holds/1,             % +Hook
            case_prove/2,             % +Hook, +Facts
            class_answer/1,           % +Hook
            case_info/2,              % +Case, -Info
            tool_vocabulary/2,        % +Case, -Classes
            size_context_facts/1,     % -Indicators
            catalogue_predicates/2,   % +Case, -Indicators
            case_missing_hooks/2,     % +Case, -Indicators
            catalogue_ranges/3        % +Case, +Facts, -Ranges
          ]).

/** <module> How the engine asks a case: hook predicates of the ontology

A tool-use case (the hook and tube, the wedge and door, ...) is data: one file
ontology/cases/<case>.pl that answers the engine's *hook predicates*, plain predicates
of the knowledge base (module `kb`, knowledge.pl) whose first argument is the case, as
SWI-Prolog's libraries call the `multifile` hooks their clients define.  The engine
modules never name a case, a tool class or a scene object: each asks the ontology
through this module, and each documents the hooks it calls (ontology/README.md has the
table).  Tool classes answer the hooks whose first argument is a class
(ontology/kinds/<class>.pl).

A hook that a case (class) does not answer at all, no clause of the predicate having
that case (class) as its first argument, raises

    error(existence_error(case_hook(Case), Name/Arity), _)
    error(existence_error(class_hook(Class), Name/Arity), _)

never a silent failure; an undeclared case raises existence_error(case, Case).  A hook
clause whose first argument is a variable (the robot's own pick_up/1 skill) answers
for every case.

The hooks read here:

  - case(?Case): Case is a tool-use case (one fact per case file).
  - task_roles(?Case, ?Target, ?Context): the object a tool acts on and the object or
    place the action happens in, e.g. task_roles(hook, cube1, tube1).
*/

:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(knowledge, [kb_clause/2, kb_holds/1, kb_prove/2]).

%!  must_be_case(+Case) is det.
%
%   Case is a case the ontology declares (case/1).
%
%   @error instantiation_error or type_error(atom, Case) if Case is not an atom.
%   @error existence_error(case, Case) if no ontology file declares it.
%
%   ==
%   ?- must_be_case(hook).
%   true.
%   ?- must_be_case(kitchen).
%   ERROR: case `kitchen' does not exist
%   ==
must_be_case(Case) :-
    must_be(atom, Case),
    (   kb_clause(case(Case), true)
    ->  true
    ;   existence_error(case, Case)
    ).

%!  case_roles(+Case, -Target, -Context) is det.
%
%   The target and context objects of Case (task_roles/3).
%
%   ==
%   ?- case_roles(wedge, T, C).
%   T = door1, C = floor1.
%   ==
case_roles(Case, Target, Context) :-
    must_be_case(Case),
    case_answer(task_roles(Case, Target, Context)).

%!  case_answer(+Hook) is semidet.
%
%   The first answer of the hook goal Hook, whose first argument is a declared case.
%   Fails if the case's clauses have no answer.
%
%   @error existence_error(case_hook(Case), Name/Arity) if no clause of Hook's
%          predicate is about Case.
%
%   ==
%   ?- case_answer(case_goal(hook, G)).
%   G = [out_of_tube(cube1, tube1)].
%   ==
case_answer(Hook) :-
    must_have_hook_(case, Hook),
    once(kb_holds(Hook)).

%!  case_holds(+Hook) is nondet.
%
%   Every answer of the hook goal Hook (first argument: a declared case), in clause
%   order.
%
%   @error existence_error(case_hook(Case), Name/Arity) as case_answer/1.
case_holds(Hook) :-
    must_have_hook_(case, Hook),
    kb_holds(Hook).

%!  case_prove(+Hook, +Facts:list) is nondet.
%
%   Prove the hook goal Hook (first argument: a declared case) with kb_prove/2: the
%   primitive facts its rules use come from Facts, the state at hand.
%
%   @error existence_error(case_hook(Case), Name/Arity) as case_answer/1.
%
%   ==
%   ?- case_prove(tool_in_use(hook, T), [held(h), tip_position(h, 0.95, 0.0, 0.0),
%                 tube_mouth(tube1, 0.7, 0.0, 0.0), tube_length_m(tube1, 0.3),
%                 tube_inner_m(tube1, 0.08, 0.07)]).
%   T = h.
%   ==
case_prove(Hook, Facts) :-
    must_have_hook_(case, Hook),
    kb_prove(Hook, Facts).

%!  class_answer(+Hook) is semidet.
%
%   The first answer of the hook goal Hook whose first argument is a tool class
%   (ontology/kinds/).
%
%   @error existence_error(class_hook(Class), Name/Arity) if no clause of Hook's
%          predicate is about Class.
%
%   ==
%   ?- class_answer(new_tool_kind(hook_like, [tool(t), stick(t)], K)).
%   K = stick.
%   ==
class_answer(Hook) :-
    must_have_hook_(class, Hook),
    once(kb_holds(Hook)).

%   must_have_hook_(+Type, +Hook): some clause of Hook's predicate has Hook's first
%   argument (or a variable) as its own first argument.
must_have_hook_(Type, Hook) :-
    must_be(compound, Hook),
    compound_name_arity(Hook, Name, Arity),
    arg(1, Hook, Key),
    (   Type == case
    ->  must_be_case(Key)
    ;   must_be(atom, Key)
    ),
    functor(Template, Name, Arity),
    arg(1, Template, Key),
    (   kb_clause(Template, _)
    ->  true
    ;   hook_error_type_(Type, Key, ErrorType),
        existence_error(ErrorType, Name/Arity)
    ).

hook_error_type_(case, Case, case_hook(Case)).
hook_error_type_(class, Class, class_hook(Class)).

%!  case_info(+Case, -Info) is det.
%
%   Info = case(Skills, Goal, Target, Context, PoseTerm): what a case manifest
%   (worlds/<case>/case.toml) must agree with.  Skills are the innate skill names in
%   plan order (case_skills/2), Goal the goal literals (case_goal/2), Target and Context
%   the role objects (task_roles/3), PoseTerm the name of the pose term (pose_domain/3).
%
%   ==
%   ?- case_info(hook, I).
%   I = case([pick_up, position_tool, pull], [out_of_tube(cube1, tube1)],
%            cube1, tube1, hook_pose).
%   ==
case_info(Case, case(Skills, Goal, Target, Context, PoseTerm)) :-
    case_roles(Case, Target, Context),
    case_answer(case_skills(Case, Skills)),
    case_answer(case_goal(Case, Goal)),
    case_answer(pose_domain(Case, Pose, _)),
    functor(Pose, PoseTerm, _).


%!  tool_vocabulary(+Case, -Classes:list) is det.
%
%   Classes lists class(Class, Ancestors, Properties) for the case's tool class
%   (case_tool_class/2) and every class below it (subclass_of/2), in the order the
%   ontology declares them: Ancestors are the classes above Class, outermost first (the
%   class literals every tool of Class carries besides Class itself); Properties are
%   Property-Values pairs for every class_property/2 of Class and its ancestors, the
%   values from qualitative_range/5, else from size_choice/4.  This is the vocabulary
%   of a qualitative tool spec (``creative make-tool``).
%
%   ==
%   ?- tool_vocabulary(wedge, [class(block, [object], Ps)|_]).
%   Ps = [shape-[triangular_prism, box, cylinder], block_length-[short, medium, long], ...].
%   ==
tool_vocabulary(Case, Classes) :-
    must_be_case(Case),
    case_answer(case_tool_class(Case, Root)),
    findall(C, class_below_(Root, C), Below),
    findall(class(C, Ancestors, Properties),
            ( member(C, [Root|Below]),
              class_ancestors_(C, Ancestors),
              class_properties_(C, Ancestors, Properties) ),
            Classes).

class_below_(Root, C) :-
    kb_holds(subclass_of(C1, Root)),
    (   C = C1
    ;   class_below_(C1, C)
    ).

class_ancestors_(C, Ancestors) :-
    (   kb_holds(subclass_of(C, Parent))
    ->  class_ancestors_(Parent, Above),
        append(Above, [Parent], Ancestors)
    ;   Ancestors = []
    ).

class_properties_(C, Ancestors, Properties) :-
    append(Ancestors, [C], Chain),
    findall(P-Values,
            ( member(K, Chain),
              kb_holds(class_property(K, P)),
              property_values_(P, Values) ),
            Properties).

property_values_(P, Values) :-
    findall(V, kb_holds(qualitative_range(P, V, _, _, _)), Vs0),
    (   Vs0 \== []
    ->  Values = Vs0
    ;   once(kb_holds(size_choice(_, _, P, Values)))
    ->  true
    ;   Values = []
    ).


%!  size_context_facts(-Indicators:list) is det.
%
%   Indicators are the Name/Arity of every task fact the size model reads from a
%   context: the facts size_constraint/3 of the tool kinds and cases are about (a
%   tube's length, a door's gap, ...) and the margins of size_parameter/3, in the order
%   the ontology declares them.
%
%   ==
%   ?- size_context_facts(Fs), memberchk(max_tool_length/1, Fs).
%   true.
%   ==
size_context_facts(Indicators) :-
    findall(N/A, ( kb_holds(size_constraint(_, Fact, _)), functor(Fact, N, A) ), Is0),
    findall(N/1, kb_holds(size_parameter(N, _, _)), Is1),
    append(Is0, Is1, Is),
    list_to_set(Is, Indicators).


%!  catalogue_predicates(+Case, -Indicators:list) is det.
%
%   Indicators are the Name/Arity of the catalogue facts of the case's tool class
%   (catalogue_predicate/2 of case_tool_class/2): the vocabulary in which the world
%   describes its objects to the robot (object_kind/2, handle_length_m/2, ...).
%
%   ==
%   ?- catalogue_predicates(wedge, Is).
%   Is = [object_kind/2, block_shape/2, block_length_m/2, block_width_m/2,
%         block_height_m/2].
%   ==
catalogue_predicates(Case, Indicators) :-
    must_be_case(Case),
    case_answer(case_tool_class(Case, Class)),
    findall(PI, kb_holds(catalogue_predicate(Class, PI)), Indicators).

%!  catalogue_ranges(+Case, +Facts:list, -Ranges:list) is det.
%
%   Ranges lists range(Object, Fact, Number, Property, Value, Low, High, Bounds) for
%   every numeric catalogue fact Fact(Object, Number) of Facts that a structural rule
%   of the case's tool hierarchy turns into a qualitative value: the rule
%   Property(T, V) :- ..., Fact(T, X), ..., qualitative_value(Property, X, V) and the
%   qualitative_range/5 of the value Number takes.  A number no rule reads directly
%   (a stick's zero prong) or outside every range has no entry.  A randomised world
%   draws each catalogued number inside its entry, so every object keeps its
%   qualitative values.
%
%   ==
%   ?- catalogue_ranges(hook, [object_kind(h, hook), handle_length_m(h, 0.35)], R).
%   R = [range(h, handle_length_m, 0.35, handle_length, medium, 0.25, 0.45, closed_open)].
%   ==
catalogue_ranges(Case, Facts, Ranges) :-
    must_be_case(Case),
    must_be(list, Facts),
    case_answer(case_tool_class(Case, Class)),
    findall(range(Obj, F, X, P, V, Lo, Hi, B),
            ( member(Fact, Facts),
              compound(Fact),
              Fact =.. [F, Obj, X],
              number(X),
              kb_holds(catalogue_predicate(Class, F/2)),
              fact_property_(F, P),
              kb_clause(qualitative_range(P, V, Lo, Hi, B), true),
              in_range_(B, X, Lo, Hi) ),
            Ranges0),
    list_to_set(Ranges0, Ranges).

%   fact_property_(+Fact, -Property): a structural rule reads Fact's number into
%   Property's qualitative value.
fact_property_(F, P) :-
    findall(P0,
            ( kb_clause(qualitative_range(P0, _, _, _, _), true) ),
            Ps0),
    list_to_set(Ps0, Ps),
    member(P, Ps),
    functor(Head, P, 2),
    kb_clause(Head, Body),
    body_goal_(Body, G),
    G =.. [F, _, X],
    body_goal_(Body, qualitative_value(P1, Y, _)),
    P1 == P,
    X == Y,
    !.

body_goal_((A, B), G) :-
    !,
    (   body_goal_(A, G)
    ;   body_goal_(B, G)
    ).
body_goal_(G, G).

in_range_(closed_open, X, Lo, Hi) :- X >= Lo, X < Hi.
in_range_(closed_closed, X, Lo, Hi) :- X >= Lo, X =< Hi.
in_range_(open_closed, X, Lo, Hi) :- X > Lo, X =< Hi.

%!  case_missing_hooks(+Case, -Missing:list) is det.
%
%   Missing are the Name/Arity of the hook predicates the engine asks of every case
%   (required_hook_/1) that Case does not answer: no clause of the predicate has Case,
%   or a variable, as its first argument.  Checked once before a run, so that a case
%   file lacking a hook is named at once instead of when the engine first needs it.
%
%   ==
%   ?- case_missing_hooks(hook, M).
%   M = [].
%   ==
case_missing_hooks(Case, Missing) :-
    must_be_case(Case),
    findall(Name/Arity,
            ( required_hook_(Name/Arity),
              functor(Template, Name, Arity),
              arg(1, Template, Case),
              \+ kb_clause(Template, _) ),
            Missing).

required_hook_(task_roles/3).
required_hook_(case_goal/2).
required_hook_(case_skills/2).
required_hook_(case_tool_class/2).
required_hook_(case_extra_objects/2).
required_hook_(innate_skill/3).
required_hook_(learned_action_names/2).
required_hook_(tool_acts_when/2).
required_hook_(untestable_literals/2).
required_hook_(task_predicate/2).
required_hook_(tool_in_use/2).
required_hook_(relative_pose/5).
required_hook_(pose_target/5).
required_hook_(spatial_definition/4).
required_hook_(pose_domain/3).
required_hook_(geometry_default/4).
required_hook_(reach_definition/3).

