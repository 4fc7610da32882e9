:- module(action_model,
          [ innate_action_models/2,     % +Case, -Models
            action_task_goal/2,         % +Case, -Goal
            must_be_action_model/1,     % +Model
            action_model_instance/6,    % +Model, +Args, -Name, -Pre, -Add, -Del
            action_motion_tool/2,       % +Model, -Tool
            action_tool_model/2,        % +Model, -Tool
            tool_literal_kind/3,        % +Tool, +Literal, -Kind
            action_models_compile/2,    % +Models, -Compiled
            action_objects/4,           % +Models, +Literals, +Extra, -Objects
            catalogued_object/2,        % +Literal, -Object
            case_tool_objects/3         % +Case, +Literals, -Tools
          ]).

/** <module> STRIPS action models: the robot's innate skills and learned tool actions

An action model is a plain data term, threaded through arguments:

    action_model(Name, Params, Pre, Add, Del)

  - Name: an atom, the action's (and the skill's) name, e.g. `pick_up`.
  - Params: a list of `Var-Type`, Type one of `tool` (an object the robot can hold:
    hooks, sticks, blocks), `target` (the object the task is about: `cube1`, `door1`)
    and `site` (where it happens: `tube1`, `floor1`).
  - Pre: a list of literals that must hold before the action; `not(L)` means L must
    be false (only learned models refined by negative examples use it).
  - Add, Del: the literals the action makes true and false.

A *motion skill* moves a held object to a pose relative to the target.  Which spatial
literals it makes true is not fixed in advance: the schematic literal `spatial_of(T)`
in Add and Del says "any spatial literal whose first argument is the tool T may become
true or false".  In the delete list of another skill (pull) the
schema says only that T's spatial literals may become false (pulling moves the tool
out of the tube).  Learning by observation (observe.pl) uses the schema to explain
such changes of T's spatial literals; planning (planner.pl) and PDDL (pddl.pl) first
*compile* each motion skill into ordinary STRIPS actions whose add effects are exactly
the spatial literals some learned model's precondition needs
(action_models_compile/2).

The innate models (the robot's skills, given, not learned) are data of the ontology,
asked through these hook predicates (case.pl says how a missing one is reported):

  - case_skills(?Case, ?Names): the innate skills of Case, in plan order.
  - innate_skill(?Case, ?Name, ?Model): the STRIPS model of a skill (a clause with an
    unbound Case, like the robot's pick_up/1 in ontology/skills.pl, holds for every
    case).
  - case_goal(?Case, ?Goal): the goal literals of the case's task.

For the two cases of the paper (ontology/cases/hook.pl, ontology/cases/wedge.pl):

  | case  | skill                        | pre                            | add / del |
  |-------|------------------------------|--------------------------------|-----------|
  | both  | pick_up(T)                   | gripper_empty, on_table(T)     | +holding(T) -gripper_empty -on_table(T) |
  | hook  | position_tool(T, C, Tube)    | holding(T), in_tube(C, Tube)   | motion: spatial_of(T) |
  | hook  | pull(T, C, Tube)             | holding(T)                     | -in_tube(T, Tube), -spatial_of(T) |
  | wedge | place(W, D, Floor)           | holding(W), door_open(D)       | motion: spatial_of(W); +gripper_empty -holding(W) |
  | wedge | release_door(D)              | door_open(D)                   | none (the door's closing is the world's response) |

Literals are classified relative to a tool (tool_literal_kind/3) by the ontology, whatever
the case: *structural* (structural_predicate(?Class, ?Name/Arity) of a tool class:
tool/1, handle_length/2, shape/2, ...) and *spatial* (a spatial_definition/4 of some
case: behind/2, hook_down/1, near/2, ...) when their first argument is the tool;
*robot* (gripper_empty/0, holding/1, on_table/1, the robot's own state);
*catalogue* (catalogue_predicate(?Class, ?Name/Arity): the numeric facts
object_kind/2, handle_length_m/2, block_length_m/2, ...) when their first argument is
the tool; anything else is *other* (task literals such as in_tube(cube1, tube1),
door_held(door1)).  An object is *catalogued* (catalogued_object/2) when a literal of
a hierarchy's root class (a class without a superclass in subclass_of/2: tool/1,
object/1) names it.
*/

:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(error)).
:- use_module(case).

%!  innate_action_models(+Case, -Models) is det.
%
%   Models is the list of the robot's innate action models for Case (a case of
%   ontology/cases/), in the order of case_skills/2, with fresh variables.
%
%       ?- innate_action_models(hook, Ms), length(Ms, N).
%       N = 3.
%
%   @error existence_error(case, Case) for a case no ontology file declares.
%   @error existence_error(innate_skill(Case), Name) for a listed skill without a model.

innate_action_models(Case, Models) :-
    must_be_case(Case),
    case_answer(case_skills(Case, Names)),
    maplist(innate_model_(Case), Names, Models).

innate_model_(Case, Name, Model) :-
    (   case_answer(innate_skill(Case, Name, Model0))
    ->  Model = Model0
    ;   existence_error(innate_skill(Case), Name)
    ).

%!  action_task_goal(+Case, -Goal) is det.
%
%   Goal is the list of literals the task of Case asks for (case_goal/2, the world
%   files' object names).
%
%       ?- action_task_goal(wedge, G).
%       G = [door_held(door1)].
%
%   @error existence_error(case, Case) for a case no ontology file declares.

action_task_goal(Case, Goal) :-
    case_answer(case_goal(Case, Goal)).

%!  must_be_action_model(+Model) is det.
%
%   Succeed if Model is a well-formed action_model/5 term; raise otherwise.
%
%       ?- must_be_action_model(action_model(a, [X-tool], [p(X)], [], [])).
%       true.
%
%   @error type_error(action_model, Model) if Model is not an action_model/5 term,
%          or its name is not an atom, or a part is not a list.
%   @error domain_error(action_parameter, P) if a parameter is not Var-Type with an
%          unbound Var and Type in tool, target, site.

must_be_action_model(Model) :-
    (   Model = action_model(Name, Params, Pre, Add, Del),
        atom(Name),
        is_list(Params), is_list(Pre), is_list(Add), is_list(Del)
    ->  maplist(must_be_param_, Params)
    ;   type_error(action_model, Model)
    ).

must_be_param_(P) :-
    (   P = V-Type, var(V), atom(Type), memberchk(Type, [tool, target, site])
    ->  true
    ;   domain_error(action_parameter, P)
    ).

%!  action_model_instance(+Model, +Args, -Name, -Pre, -Add, -Del) is det.
%
%   Pre, Add and Del are a fresh copy of Model's lists with its parameters bound to
%   Args, in order.
%
%       ?- innate_action_models(hook, [M|_]),
%          action_model_instance(M, [hook_a2], N, Pre, _, _).
%       N = pick_up, Pre = [gripper_empty, on_table(hook_a2)].
%
%   @error domain_error(arguments_of(Name), Args) if Args has the wrong length.

action_model_instance(Model, Args, Name, Pre, Add, Del) :-
    must_be_action_model(Model),
    must_be(list, Args),
    copy_term(Model, action_model(Name, Params, Pre, Add, Del)),
    pairs_keys(Params, Vars),
    (   same_length(Vars, Args)
    ->  Vars = Args
    ;   domain_error(arguments_of(Name), Args)
    ).

%!  action_motion_tool(+Model, -Tool) is semidet.
%
%   True if Model is a motion skill (its Add holds the schema `spatial_of(Tool)`).
%
%       ?- innate_action_models(hook, [_, M|_]), action_motion_tool(M, T),
%          M = action_model(position_tool, [P-tool|_], _, _, _), T == P.
%       true.

action_motion_tool(action_model(_, _, _, Add, _), Tool) :-
    memberchk(spatial_of(Tool), Add).

%!  action_tool_model(+Model, -Tool) is semidet.
%
%   True if Model is a *tool action*: it has a parameter Tool of type `tool` and its
%   precondition holds at least one structural literal of Tool or, where any tool
%   worked, a spatial one (a learned model).
%
%       ?- action_tool_model(action_model(pull_out, [T-tool, C-target],
%                                         [hook(T), behind(T, C)], [], []), X).
%       X = T.

action_tool_model(action_model(_, Params, Pre, _, _), Tool) :-
    member(Tool-tool, Params),
    member(L, Pre),
    tool_literal_kind(Tool, L, Kind),
    tool_model_kind_(Kind),
    !.

%   A learned model needs a structural literal of its tool or, when any tool of the
%   hierarchy worked, a spatial one (the pose); no innate model's precondition holds
%   either.
tool_model_kind_(structural).
tool_model_kind_(spatial).

%!  tool_literal_kind(+Tool, +Literal, -Kind) is det.
%
%   Kind is `structural`, `spatial` or `catalogue` if Literal is a structural,
%   spatial or catalogue (numeric: handle_length_m/2, ...) literal whose first
%   argument is Tool (compared with ==, so Tool may be a variable of a model),
%   `robot` for the robot's own state, and `other` otherwise.  A negated
%   literal not(L) has the kind of L.
%
%       ?- tool_literal_kind(hook_a2, behind(hook_a2, cube1), K).
%       K = spatial.
%       ?- tool_literal_kind(hook_a2, in_tube(cube1, tube1), K).
%       K = other.

tool_literal_kind(Tool, Literal, Kind) :-
    (   var(Literal)
    ->  instantiation_error(Literal)
    ;   Literal = not(L)
    ->  tool_literal_kind(Tool, L, Kind)
    ;   callable(Literal)
    ->  functor(Literal, F, N),
        literal_kind_(F/N, Literal, Tool, Kind)
    ;   type_error(literal, Literal)
    ).

literal_kind_(PI, Literal, Tool, Kind) :-
    (   robot_predicate_(PI)
    ->  Kind = robot
    ;   compound(Literal), arg(1, Literal, A), A == Tool, structural_predicate_(PI)
    ->  Kind = structural
    ;   compound(Literal), arg(1, Literal, A), A == Tool, spatial_predicate_(PI)
    ->  Kind = spatial
    ;   compound(Literal), arg(1, Literal, A), A == Tool, catalogue_predicate_(PI)
    ->  Kind = catalogue
    ;   Kind = other
    ).

robot_predicate_(gripper_empty/0).
robot_predicate_(holding/1).
robot_predicate_(on_table/1).

structural_predicate_(PI) :-
    once(ontology_holds(structural_predicate(_, PI))).

catalogue_predicate_(PI) :-
    once(ontology_holds(catalogue_predicate(_, PI))).

spatial_predicate_(N/A) :-
    functor(Template, N, A),
    once(ontology_holds(spatial_definition(_, Template, _, _))).

%!  catalogued_object(+Literal, -Object) is semidet.
%
%   Literal is C(Object) with C the root class of a tool hierarchy (tool/1, object/1):
%   Object is a catalogued object the robot may use.
%
%       ?- catalogued_object(tool(hook_a2), O).
%       O = hook_a2.
%       ?- catalogued_object(hook(hook_a2), O).
%       false.

catalogued_object(Literal, Object) :-
    compound(Literal),
    compound_name_arguments(Literal, Class, [Object]),
    once(ontology_holds(subclass_of(_, Class))),
    \+ ontology_holds(subclass_of(Class, _)).

%!  case_tool_objects(+Case, +Literals, -Tools) is det.
%
%   Tools is the sorted list of the objects of Literals that can be a tool of Case:
%   every X of a class literal C(X) with C a class of the case's tool hierarchy
%   (case:tool_vocabulary/2: the case's tool class, case_tool_class/2, the classes
%   below it and the classes above it by subclass_of/2), or a catalogued object
%   (catalogued_object/2).  What h_g keeps of the class literals does not matter:
%   the types come from the ontology and the catalogue's literals of the state.
%
%       ?- case_tool_objects(hook, [hook_like(h1), stick(s1), in_tube(cube1, tube1),
%                                   handle_length(h1, medium)], Ts).
%       Ts = [h1, s1].
%
%   @error existence_error(case, Case) for a case no ontology file declares.

case_tool_objects(Case, Literals, Tools) :-
    must_be(list, Literals),
    tool_vocabulary(Case, Classes),
    findall(C, ( member(class(K, Above, _), Classes), member(C, [K|Above]) ), Cs0),
    sort(Cs0, Cs),
    findall(X, ( member(L, Literals),
                 compound(L),
                 compound_name_arguments(L, C, [X]),
                 atom(X),
                 (   memberchk(C, Cs)
                 ->  true
                 ;   catalogued_object(L, X)
                 ) ),
            Xs),
    sort(Xs, Tools).

%!  action_models_compile(+Models, -Compiled) is det.
%
%   Compiled holds the ordinary (non-motion) models of Models in order, with any
%   spatial_of/1 schema removed from their effects (STRIPS keeps only the named
%   literals), followed by one ordinary STRIPS action per pair (motion skill M, tool action L)
%   where L needs spatial literals of its tool.  The compiled action has M's
%   parameters and precondition; it adds M's plain add effects plus L's positive
%   spatial literals of the tool and deletes M's plain delete effects plus the
%   literals L requires false (`not(S)`) and the spatial literals the other compiled
%   actions of M add.  M's parameters are matched to L's by type, the first of each
%   type; a spatial literal mentioning a variable that is not one of M's parameters is
%   left out (the motion cannot establish it).  The action is named like M if M
%   serves one tool action, else M_for_L.  A motion skill that serves no tool action
%   is dropped: it has no effect a plan could use.
%
%       ?- innate_action_models(hook, Ms),
%          L = action_model(pull_out, [T-tool, C-target, U-site],
%                           [holding(T), hook(T), behind(T, C)], [out_of_tube(C, U)], []),
%          action_models_compile([L|Ms], Cs), last(Cs, P).
%       P = action_model(position_tool, [T1-tool, C1-target, U1-site],
%                        [holding(T1), in_tube(C1, U1)], [behind(T1, C1)], []).

action_models_compile(Models, Compiled) :-
    must_be(list, Models),
    maplist(must_be_action_model, Models),
    partition(is_motion_, Models, Motions, Plain0),
    maplist(strip_schema_, Plain0, Plain),
    include([M]>>action_tool_model(M, _), Plain, ToolModels),
    maplist(compile_motion_(ToolModels), Motions, MotionLists),
    append(MotionLists, Compiled0),
    append(Plain, Compiled0, Compiled).

is_motion_(M) :-
    action_motion_tool(M, _).

strip_schema_(action_model(N, Ps, Pre, Add0, Del0), action_model(N, Ps, Pre, Add, Del)) :-
    exclude(is_schema_, Add0, Add),
    exclude(is_schema_, Del0, Del).

is_schema_(spatial_of(_)).

compile_motion_(ToolModels, Motion, Actions) :-
    maplist(motion_purpose_(Motion), ToolModels, Purposes0),
    exclude(==(none), Purposes0, Purposes),
    length(Purposes, N),
    maplist(motion_action_(Motion, N, Purposes), Purposes, Actions).

%   motion_purpose_(+Motion, +ToolModel, -Purpose): purpose(LName, Params, Add, Del)
%   in terms of a fresh copy of Motion's parameters, or none.
motion_purpose_(Motion, ToolModel, Purpose) :-
    copy_term(Motion, action_model(_, MParams, _, _, _)),
    copy_term(ToolModel, action_model(LName, LParams, LPre, _, _)),
    action_tool_model(action_model(LName, LParams, LPre, [], []), LTool),
    match_params_by_type_(LParams, MParams),
    term_variables(MParams, MVars),
    include(motion_literal_(LTool, MVars), LPre, Spatial),
    (   Spatial == []
    ->  Purpose = none
    ;   partition([L]>>(L \= not(_)), Spatial, Pos, Neg0),
        maplist([not(X), X]>>true, Neg0, Neg),
        Purpose = purpose(LName, MParams, Pos, Neg)
    ).

match_params_by_type_(LParams, MParams) :-
    maplist(match_type_(LParams, MParams), [tool, target, site]).

match_type_(LParams, MParams, Type) :-
    (   memberchk(V-Type, LParams),
        memberchk(W-Type, MParams)
    ->  V = W
    ;   true
    ).

motion_literal_(Tool, MVars, L) :-
    tool_literal_kind(Tool, L, spatial),
    term_variables(L, Vs),
    forall(member(V, Vs), ( member(W, MVars), W == V )).

motion_action_(Motion, N, Purposes, purpose(LName, Params, Pos, Neg), Action) :-
    copy_term(Motion, action_model(MName, MParams, MPre, MAdd, MDel)),
    MParams = Params,
    exclude(is_schema_, MAdd, Add0),
    exclude(is_schema_, MDel, Del0),
    findall(Params-S, ( member(purpose(Other, Params, OPos, _), Purposes),
                        Other \== LName,
                        member(S, OPos)
                      ),
            OtherPairs),
    maplist(rebind_(Params), OtherPairs, OthersAdd0),
    exclude(memberchk_eq_(Pos), OthersAdd0, OthersAdd),
    append(Add0, Pos, Add1),
    append([Del0, Neg, OthersAdd], Del1),
    dedupe_(Add1, Add),
    dedupe_(Del1, Del),
    (   N =:= 1
    ->  Name = MName
    ;   atomic_list_concat([MName, '_for_', LName], Name)
    ),
    Action = action_model(Name, MParams, MPre, Add, Del).

rebind_(Params, Params-S, S).

memberchk_eq_(Xs, X) :-
    member(Y, Xs),
    Y == X,
    !.

dedupe_([], []).
dedupe_([X|Xs], Ys) :-
    (   member(Y, Xs), Y == X
    ->  Ys = Ys1
    ;   Ys = [X|Ys1]
    ),
    dedupe_(Xs, Ys1).

%!  action_objects(+Models, +Literals, +Extra, -Objects) is det.
%
%   Objects is the sorted list of Name-Type for every constant of the ground
%   Literals, plus Extra (a list of Name-Type that wins over inference).  A constant
%   is a `tool` if it is catalogued (catalogued_object/2: tool(X) or object(X) is among
%   Literals); otherwise it takes the
%   type, other than `tool`, of a model parameter that occupies the same argument position of the same
%   predicate in some model (precondition, add or delete list, models in order);
%   otherwise it is a `value` (a qualitative value such as `medium`).
%
%       ?- innate_action_models(hook, Ms),
%          action_objects(Ms, [on_table(hook_a1), tool(hook_a1),
%                              in_tube(cube1, tube1)], [], Os).
%       Os = [cube1-target, hook_a1-tool, tube1-site].

action_objects(Models, Literals, Extra, Objects) :-
    must_be(list, Models),
    must_be(list, Literals),
    must_be(list, Extra),
    maplist(must_be_ground_literal_, Literals),
    findall(C, ( member(L, Literals), L =.. [_|Args], member(C, Args) ), Cs0),
    pairs_keys(Extra, ExtraNames),
    sort(Cs0, Cs1),
    subtract(Cs1, ExtraNames, Cs),
    maplist(constant_type_(Models, Literals), Cs, Typed),
    append(Extra, Typed, Objects0),
    sort(Objects0, Objects).

must_be_ground_literal_(L) :-
    (   ground(L), callable(L)
    ->  true
    ;   type_error(ground_literal, L)
    ).

constant_type_(Models, Literals, C, C-Type) :-
    must_be(atom, C),
    (   member(L, Literals),
        catalogued_object(L, O),
        O == C
    ->  Type = tool
    ;   member(M, Models),
        M = action_model(_, Params, Pre, Add, Del),
        append([Pre, Add, Del], Ls),
        member(ML, Ls),
        ML \= not(_),
        member(SL, Literals),
        compound(SL),
        functor(ML, F, N), functor(SL, F, N),
        arg(I, SL, A), A == C,
        arg(I, ML, V), var(V),
        member(W-Type, Params), W == V,
        Type \== tool
    ->  true
    ;   Type = value
    ).
