:- module(case,
          [ must_be_case/1,           % +Case
            case_roles/3,             % +Case, -Target, -Context
            case_answer/1,            % +Hook
            case_holds/1,             % +Hook
            case_prove/2,             % +Hook, +Facts
            case_prove/3,             % +Case, +Goal, +Facts
            case_knowledge/2,         % +Case, ?Goal
            case_has_hook/2,          % +Case, +Name/Arity
            class_answer/1,           % +Hook
            class_holds/1,            % +Hook
            ontology_holds/1,         % ?Goal
            case_info/2,              % +Case, -Info
            tool_vocabulary/2,        % +Case, -Classes
            size_context_facts/1,     % -Indicators
            size_context_facts/2,     % +Case, -Indicators
            catalogue_predicates/2,   % +Case, -Indicators
            case_missing_hooks/2,     % +Case, -Indicators
            catalogue_ranges/3        % +Case, +Facts, -Ranges
          ]).

/** <module> How the engine asks a case: hook predicates of the ontology

A tool-use case (the hook and tube, the wedge and door, ...) is data: one file
ontology/cases/<case>.pl that answers the engine's *hook predicates*, plain predicates
whose first argument is the case, as SWI-Prolog's libraries call the `multifile` hooks
their clients define.  Each case file loads into its own module (`case_<case>`,
knowledge.pl), which sees its tool kind's module (`kind_<kind>`, ontology/kinds/), the
modules of the apparatus it shares with other cases (`apparatus_<name>`,
ontology/apparatus/, named by case_apparatus/2) and the shared knowledge (`kb`); so two
cases may define the same helper predicate, and a case's rules constrain only its own
tools.  The engine modules never name a case, a
tool class or a scene object: each asks the ontology through this module, naming the
case (or the class), and each documents the hooks it calls (ontology/README.md has the
table).  Tool classes answer the hooks whose first argument is a class
(ontology/kinds/<kind>.pl).

A case's *namespace* is its module, its kind's module, its apparatus' modules and
`kb`, in this order (knowledge:kb_module_scope/2).  A hook's answers are those of every module of the
namespace that defines the hook predicate, in this order (a clause with an unbound
case, the robot's own pick_up/1 skill in the shared skills.pl, answers for every case).
A hook that a case (class) does not answer at all, no clause of the predicate in its
namespace having that case (class) or a variable as its first argument, raises

    error(existence_error(case_hook(Case), Name/Arity), _)
    error(existence_error(class_hook(Class), Name/Arity), _)

never a silent failure; an undeclared case raises existence_error(case, Case).
case_prove/3 proves any goal of the case's namespace (a task or structural literal)
and raises existence_error(case_hook(Case), Name/Arity) when no module of it defines
the predicate; case_knowledge/2 reads optional knowledge of the namespace (a size
model's facts) and fails when there is none.  ontology_holds/1 is the one read across
every module, for the questions that name no case (is this a spatial literal of some
case?).

The hooks read here:

  - case(?Case): Case is a tool-use case (one fact per case file).
  - kind(?Kind): Kind is a tool kind (one fact per kind file).
  - task_roles(?Case, ?Target, ?Context): the object a tool acts on and the object or
    place the action happens in, e.g. task_roles(hook, cube1, tube1).
*/

:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(knowledge, [kb_case_module/2, kb_kind_module/2, kb_modules/1,
                          kb_module_scope/2, kb_module_defines/2, kb_module_holds/2,
                          kb_module_clause/3, kb_module_prove/3]).

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
    (   kb_case_module(Case, _)
    ->  true
    ;   existence_error(case, Case)
    ).

%   case_scope_(+Case, -Scope): the modules of the case's namespace, its own first.
case_scope_(Case, Scope) :-
    kb_case_module(Case, M),
    !,
    kb_module_scope(M, Scope).

%   class_scope_(+Class, -Scope): the modules of the kind that declares Class (kind/1)
%   or names it in its hierarchy (subclass_of/2), then kb; fails for an unknown class.
class_scope_(Class, Scope) :-
    (   kb_kind_module(Class, M)
    ->  true
    ;   kb_kind_module(_, M),
        kb_module_defines(M, subclass_of/2),
        (   M:subclass_of(Class, _)
        ;   M:subclass_of(_, Class)
        )
    ->  true
    ),
    kb_module_scope(M, Scope).

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
%   The first answer of the hook goal Hook, whose first argument is a declared case, in
%   the case's namespace.  Fails if the case's clauses have no answer.
%
%   @error existence_error(case_hook(Case), Name/Arity) if no clause of Hook's
%          predicate is about Case.
%
%   ==
%   ?- case_answer(case_goal(hook, G)).
%   G = [out_of_tube(cube1, tube1)].
%   ==
case_answer(Hook) :-
    once(case_holds(Hook)).

%!  case_holds(+Hook) is nondet.
%
%   Every answer of the hook goal Hook (first argument: a declared case) in the case's
%   namespace, module by module, in clause order.
%
%   @error existence_error(case_hook(Case), Name/Arity) as case_answer/1.
case_holds(Hook) :-
    hook_scope_(case, Hook, Scope),
    member(M, Scope),
    kb_module_holds(M, Hook).

%!  case_prove(+Hook, +Facts:list) is nondet.
%
%   Prove the hook goal Hook (first argument: a declared case) in the case's namespace
%   with knowledge:kb_module_prove/3: the primitive facts its rules use come from
%   Facts, the state at hand.
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
    hook_scope_(case, Hook, Scope),
    functor(Hook, N, A),
    member(M, Scope),
    kb_module_defines(M, N/A),
    kb_module_prove(M, Hook, Facts).

%!  case_prove(+Case, +Goal, +Facts:list) is nondet.
%
%   Prove Goal, a predicate of the namespace of Case (a task literal of its file, a
%   structural literal of its kind), in the case's module: its rules see the case's
%   own predicates, its kind's and the shared ones, and take their primitive facts
%   from Facts.
%
%   @error existence_error(case_hook(Case), Name/Arity) if no module of the case's
%          namespace defines Goal's predicate.
%
%   ==
%   ?- case_prove(hook, handle_length(h, V), [object_kind(h, hook), handle_length_m(h, 0.5)]).
%   V = long.
%   ==
case_prove(Case, Goal, Facts) :-
    must_be_case(Case),
    must_be(callable, Goal),
    case_scope_(Case, [M|Scope]),
    functor(Goal, N, A),
    (   member(D, [M|Scope]),
        kb_module_defines(D, N/A)
    ->  kb_module_prove(M, Goal, Facts)
    ;   existence_error(case_hook(Case), N/A)
    ).

%!  case_knowledge(+Case, ?Goal) is nondet.
%
%   Goal holds in a module of the namespace of Case (its own, its kind's, the shared
%   one), module by module: the optional knowledge a case may or may not have (a size
%   model's facts, a qualitative range).  Fails when no module defines Goal's
%   predicate.
%
%   ==
%   ?- case_knowledge(wedge, size_field(block, F, P)).
%   F = length, P = block_length .
%   ==
case_knowledge(Case, Goal) :-
    must_be_case(Case),
    must_be(callable, Goal),
    case_scope_(Case, Scope),
    member(M, Scope),
    kb_module_holds(M, Goal).

%!  case_has_hook(+Case, +Name/Arity) is semidet.
%
%   Some clause of Name/Arity in the case's namespace has Case, or a variable, as its
%   first argument: the case answers the hook (optional hooks such as geometry_value/6
%   are asked only then).
case_has_hook(Case, Name/Arity) :-
    must_be_case(Case),
    functor(Template, Name, Arity),
    arg(1, Template, Case),
    case_scope_(Case, Scope),
    member(M, Scope),
    kb_module_clause(M, Template, _),
    !.

%!  class_answer(+Hook) is semidet.
%
%   The first answer of the hook goal Hook whose first argument is a tool class
%   (ontology/kinds/), in its kind's module, then the shared one.
%
%   @error existence_error(class_hook(Class), Name/Arity) if no clause of Hook's
%          predicate is about Class.
%
%   ==
%   ?- class_answer(new_tool_kind(hook_like, [tool(t), stick(t)], K)).
%   K = stick.
%   ==
class_answer(Hook) :-
    once(class_holds(Hook)).

%!  class_holds(+Hook) is nondet.
%
%   Every answer of the class hook goal Hook, as class_answer/1.
%
%   @error existence_error(class_hook(Class), Name/Arity) as class_answer/1.
class_holds(Hook) :-
    hook_scope_(class, Hook, Scope),
    member(M, Scope),
    kb_module_holds(M, Hook).

%!  ontology_holds(?Goal) is nondet.
%
%   Goal holds in some module of the loaded ontology (kb, then the case and kind
%   modules in load order): the one read across every case, for questions that name
%   no case (is N/A a spatial literal of some case, a structural predicate of some
%   kind?).
%
%   ==
%   ?- ontology_holds(case(C)).
%   C = hook ; C = rake ; C = wedge.
%   ==
ontology_holds(Goal) :-
    must_be(callable, Goal),
    kb_modules(Modules),
    member(M, Modules),
    kb_module_holds(M, Goal).

%   hook_scope_(+Type, +Hook, -Scope): the namespace of Hook's case (class), after
%   checking that some clause of Hook's predicate there has Hook's first argument (or
%   a variable) as its own first argument.
hook_scope_(Type, Hook, Scope) :-
    must_be(compound, Hook),
    compound_name_arity(Hook, Name, Arity),
    arg(1, Hook, Key),
    (   Type == case
    ->  must_be_case(Key),
        case_scope_(Key, Scope)
    ;   must_be(atom, Key),
        (   class_scope_(Key, Scope0)
        ->  Scope = Scope0
        ;   Scope = []
        )
    ),
    functor(Template, Name, Arity),
    arg(1, Template, Key),
    (   member(M, Scope),
        kb_module_clause(M, Template, _)
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
    findall(C, class_below_(Case, Root, C), Below),
    findall(class(C, Ancestors, Properties),
            ( member(C, [Root|Below]),
              class_ancestors_(Case, C, Ancestors),
              class_properties_(Case, C, Ancestors, Properties) ),
            Classes).

class_below_(Case, Root, C) :-
    case_knowledge(Case, subclass_of(C1, Root)),
    (   C = C1
    ;   class_below_(Case, C1, C)
    ).

class_ancestors_(Case, C, Ancestors) :-
    (   case_knowledge(Case, subclass_of(C, Parent))
    ->  class_ancestors_(Case, Parent, Above),
        append(Above, [Parent], Ancestors)
    ;   Ancestors = []
    ).

class_properties_(Case, C, Ancestors, Properties) :-
    append(Ancestors, [C], Chain),
    findall(P-Values,
            ( member(K, Chain),
              case_knowledge(Case, class_property(K, P)),
              property_values_(Case, P, Values) ),
            Properties).

property_values_(Case, P, Values) :-
    findall(V, case_knowledge(Case, qualitative_range(P, V, _, _, _)), Vs0),
    (   Vs0 \== []
    ->  Values = Vs0
    ;   once(case_knowledge(Case, size_choice(_, _, P, Values)))
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
    size_context_indicators(ontology_holds, Indicators).

%!  size_context_facts(+Case, -Indicators:list) is det.
%
%   Indicators are the Name/Arity of the task facts the size model of Case reads (its
%   own size_constraint/3 and size_parameter/3, its kind's and the shared ones), in the
%   order the ontology declares them: of what the robot perceives of the case's scene,
%   the facts that size its tools (another case's size model may read a fact this
%   scene also reports, a cube's size/4, which this case's does not).
%
%   ==
%   ?- size_context_facts(wedge, Fs), memberchk(door_gap_m/2, Fs).
%   true.
%   ==
size_context_facts(Case, Indicators) :-
    must_be_case(Case),
    size_context_indicators(case_knowledge(Case), Indicators).

%   size_context_indicators(:Holds, -Indicators): the facts of the size_constraint/3
%   and size_parameter/3 clauses that call(Holds, Clause) proves, in order, once each.
size_context_indicators(Holds, Indicators) :-
    findall(N/A, ( call(Holds, size_constraint(_, Fact, _)), functor(Fact, N, A) ), Is0),
    findall(N/1, call(Holds, size_parameter(N, _, _)), Is1),
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
    findall(PI, case_knowledge(Case, catalogue_predicate(Class, PI)), Indicators).

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
              case_knowledge(Case, catalogue_predicate(Class, F/2)),
              fact_property_(Case, F, P),
              case_knowledge(Case, qualitative_range(P, V, Lo, Hi, B)),
              in_range_(B, X, Lo, Hi) ),
            Ranges0),
    list_to_set(Ranges0, Ranges).

%   fact_property_(+Case, +Fact, -Property): a structural rule of the case's namespace
%   reads Fact's number into Property's qualitative value.
fact_property_(Case, F, P) :-
    findall(P0, case_knowledge(Case, qualitative_range(P0, _, _, _, _)), Ps0),
    list_to_set(Ps0, Ps),
    member(P, Ps),
    functor(Head, P, 2),
    case_scope_(Case, Scope),
    member(M, Scope),
    kb_module_clause(M, Head, Body),
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
%   or a variable, as its first argument, or its first answer is not of the shape the
%   engine reads (well_formed_answer_/1: case_goal/2 a non-empty list of ground
%   literals, `case_goal(hook, _)` is not; case_skills/2 a non-empty list of atoms).
%   Checked once before a run, so that a case file lacking a hook is named at once
%   instead of when the engine first needs it.
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
              (   \+ ( case_scope_(Case, Scope),
                       member(M, Scope),
                       kb_module_clause(M, Template, _) )
              ->  true
              ;   \+ well_formed_answer_(Template)
              ) ),
            Missing).

%   well_formed_answer_(+Hook): the first answer of Hook (its case bound) has the
%   shape the engine reads; a hook without a shape rule here is well formed if it
%   answers at all (the engine asks it later, naming it if it does not).
well_formed_answer_(Hook) :-
    catch(case_answer(Hook), _, fail),
    !,
    well_formed_(Hook).
well_formed_answer_(Hook) :-
    \+ shaped_hook_(Hook).

shaped_hook_(case_goal(_, _)).
shaped_hook_(case_skills(_, _)).

well_formed_(case_goal(_, Goal)) :-
    !,
    is_list(Goal), Goal \== [],
    forall(member(G, Goal), ( ground(G), callable(G) )).
well_formed_(case_skills(_, Skills)) :-
    !,
    is_list(Skills), Skills \== [],
    forall(member(S, Skills), atom(S)).
well_formed_(_).

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

