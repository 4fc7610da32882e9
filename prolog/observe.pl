:- module(observe,
          [ observe_demonstration/3,    % +Steps, +InnateModels, -Result
            observe_demonstration/4,    % +Steps, +InnateModels, +Options, -Result
            observe_transition/4        % +Step, +Model, -Added, -Deleted
          ]).

/** <module> Learning by observation: new action models from one demonstration

The trainer's demonstration arrives as a list of transitions

    step(Skill, Args, S0, S1)

one per skill the trainer used (in order), where S0 and S1 are the abstract states
(lists of ground literals, abstract_state/3) before and after the step.  Each
transition is matched against the innate model of its skill (action_model.pl):

  - the model's precondition must hold in S0;
  - every change (added: in S1 and not in S0; deleted: in S0 and not in S1) is
    *explained* if it is an add (delete) effect of the model, or a spatial literal of
    a tool T whose schema spatial_of(T) is in the model's add (delete) list: any
    spatial change of a motion skill's tool, and spatial literals of the pulled tool
    going false.

The unexplained changes of a transition are what the trainer's tool use did beyond the
skill: they become a **new action model**.

  - Name: from the skill and the first unexplained added literal (else `not_` and
    the first deleted one), as the action_names/1 option says (the case's
    learned_action_names/2: pull + out_of_tube gives `pull_out`, release_door +
    door_held gives `hold_door`); other pairs give Skill_for_Predicate (e.g.
    `pull_for_on_floor`).
  - Tool, target and context: the skill's tool argument and its other two arguments
    if it has a tool parameter (pull(T, C, Tube)); otherwise (release_door(door1)) the
    tool, target and context of the most recent earlier step whose skill has all
    three (place(wedge_a2, door1, floor1)).
  - Params: [Tool-tool, Target-target, Context-site], then the skill's other
    arguments, as variables.
  - Pre: the skill's own precondition, then the most-specific hypothesis h_s: every
    structural literal of the tool in S0, every spatial literal of the tool in S0 whose
    other arguments are the target or the context, and the task literals of S0 that
    the step deletes (in_tube(cube1, tube1)).
  - Add, Del: the skill's plain effects plus the unexplained changes.

The *example* is the ground clause the version space starts from:
`tool_pose(Tool, Target, Context) :- Body`, Body the h_s literals above (structural,
then spatial, then task, each in S0's order) as a conjunction.  If S0 also holds the
tool's catalogue numbers (handle_length_m(hook_a2, 0.35), ...; abstract_state/3 does
not add them, the caller may) they go into the example after the structural literals,
for the constrained LGG, but not into the model's precondition (a planner and PDDL
have no use for one tool's exact sizes).

A transition with no change at all is explained whatever the model says (a skill that
did nothing teaches nothing), so it is matched even if the precondition was not seen.
*/

:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(option)).
:- use_module(library(error)).
:- use_module(action_model).
:- use_module(case, [ontology_holds/1]).

%!  observe_demonstration(+Steps, +InnateModels, -Result) is det.
%
%   Same as observe_demonstration/4 with no options (no goal check).
%
%       ?- innate_action_models(wedge, Ms),
%          observe_demonstration([step(release_door, [door1],
%                                      [door_open(door1)], [door_open(door1)])],
%                                Ms, R).
%       R = no_model(nothing_to_learn).

observe_demonstration(Steps, InnateModels, Result) :-
    observe_demonstration(Steps, InnateModels, [], Result).

%!  observe_demonstration(+Steps, +InnateModels, +Options, -Result) is det.
%
%   Segment the demonstration Steps (a list of step(Skill, Args, S0, S1)) and match
%   each transition with InnateModels.  Result is
%
%     - models(Matched, NewModels, Example): Matched lists matched(I, Skill, Args)
%       for each step I (1-based) its skill's model explains; NewModels the new
%       action models from the other steps, in order; Example the ground example
%       clause of the first new model;
%     - no_model(Reason) when the demonstration teaches nothing usable, Reason one of
%       empty_demonstration, goal_not_reached(Goal) (the last state lacks a literal
%       of the goal option), unknown_skill(I, Skill), precondition_not_observed(I,
%       Skill, Missing) (the skill's precondition literals absent from S0: perception
%       or demonstration error), no_tool_for_step(I, Skill) (an unexplained change but
%       no earlier step names a tool, target and context), nothing_to_learn (every
%       transition is explained).
%
%   Options:
%
%     - goal(Goal): Goal a list of ground literals the demonstration must reach
%       (checked on the last S1);
%     - action_names(Names): Names a list of name(Skill, Effect, Name): the new model
%       of a step of Skill whose first unexplained effect has the predicate Effect is
%       called Name, other pairs Skill_for_Effect (default: the names of every case,
%       the ontology's learned_action_names/2).
%
%       ?- innate_action_models(hook, Ms),
%          observe_demonstration([], Ms, [goal([out_of_tube(cube1, tube1)])], R).
%       R = no_model(empty_demonstration).
%
%   @error type_error(demonstration_step, S) if a step is not step(Skill, Args, S0,
%          S1) with an atom, a list and two lists of ground literals.
%   @error domain_error(arguments_of(Skill), Args) if Args do not fit the skill's
%          parameters.

observe_demonstration(Steps, InnateModels, Options, Result) :-
    must_be(list, Steps),
    must_be(list, InnateModels),
    maplist(must_be_action_model, InnateModels),
    must_be(list, Options),
    maplist(must_be_step_, Steps),
    option(goal(Goal), Options, []),
    must_be(list, Goal),
    (   option(action_names(Names), Options)
    ->  must_be(list, Names)
    ;   ontology_action_names_(Names)
    ),
    (   Steps == []
    ->  Result = no_model(empty_demonstration)
    ;   last(Steps, step(_, _, _, SFinal)),
        subtract_eq_(Goal, SFinal, Missing),
        Missing \== []
    ->  Result = no_model(goal_not_reached(Goal))
    ;   observe_steps_(Steps, 1, InnateModels, Names, none, Outcomes),
        outcomes_result_(Outcomes, Result)
    ).

must_be_step_(Step) :-
    (   Step = step(Skill, Args, S0, S1),
        atom(Skill), is_list(Args), ground(Args),
        is_list(S0), is_list(S1), ground(S0), ground(S1)
    ->  true
    ;   type_error(demonstration_step, Step)
    ).

%   observe_steps_(+Steps, +I, +Models, +Names, +Frame, -Outcomes): Outcomes lists one
%   matched(I, Skill, Args), new(Model, Example) or failed(Reason) per step, stopping
%   at the first failed/1.  Frame is the last frame(Tool, Target, Context) seen.
observe_steps_([], _, _, _, _, []).
observe_steps_([Step|Steps], I, Models, Names, Frame0, [Outcome|Outcomes]) :-
    Step = step(Skill, Args, _, _),
    (   model_named_(Models, Skill, Model)
    ->  step_frame_(Model, Args, Frame0, Frame),
        observe_step_(Step, I, Model, Names, Frame, Outcome)
    ;   Frame = Frame0,
        Outcome = failed(unknown_skill(I, Skill))
    ),
    (   Outcome = failed(_)
    ->  Outcomes = []
    ;   I1 is I + 1,
        observe_steps_(Steps, I1, Models, Names, Frame, Outcomes)
    ).

model_named_(Models, Name, Model) :-
    member(Model, Models),
    Model = action_model(Name, _, _, _, _),
    !.

%   The frame (tool, target, context) of a step whose skill has all three roles.
step_frame_(Model, Args, Frame0, Frame) :-
    bound_model_(Model, Args, action_model(_, Params, _, _, _)),
    (   memberchk(T-tool, Params),
        memberchk(G-target, Params),
        memberchk(C-site, Params)
    ->  Frame = frame(T, G, C)
    ;   Frame = Frame0
    ).

%   A copy of Model with its parameters bound to Args.
bound_model_(Model, Args, Bound) :-
    action_model_instance(Model, Args, _, _, _, _),
    copy_term(Model, Bound),
    Bound = action_model(_, Params, _, _, _),
    pairs_keys_(Params, Args).

observe_step_(step(Skill, Args, S0, S1), I, Model, Names, Frame, Outcome) :-
    observe_transition(step(Skill, Args, S0, S1), Model, Added, Deleted),
    action_model_instance(Model, Args, _, Pre, _, _),
    (   Added == [], Deleted == []
    ->  Outcome = matched(I, Skill, Args)
    ;   subtract_eq_(Pre, S0, Missing),
        Missing \== []
    ->  Outcome = failed(precondition_not_observed(I, Skill, Missing))
    ;   unexplained_(Model, Args, Added, Deleted, UAdd, UDel),
        UAdd == [], UDel == []
    ->  Outcome = matched(I, Skill, Args)
    ;   Frame == none
    ->  Outcome = failed(no_tool_for_step(I, Skill))
    ;   unexplained_(Model, Args, Added, Deleted, UAdd, UDel),
        new_model_(Skill, Args, S0, Model, Names, Frame, UAdd, UDel, Outcome)
    ).

%!  observe_transition(+Step, +Model, -Added, -Deleted) is det.
%
%   Added and Deleted are the literals of Step = step(Skill, Args, S0, S1) that are
%   in S1 and not in S0, and in S0 and not in S1, in the order of S1 and S0.  Model
%   is the innate model of Skill (checked for arity against Args).
%
%       ?- innate_action_models(hook, [P|_]),
%          observe_transition(step(pick_up, [h], [gripper_empty, on_table(h)],
%                                  [holding(h)]), P, A, D).
%       A = [holding(h)], D = [gripper_empty, on_table(h)].

observe_transition(step(Skill, Args, S0, S1), Model, Added, Deleted) :-
    must_be_step_(step(Skill, Args, S0, S1)),
    action_model_instance(Model, Args, _, _, _, _),
    subtract_eq_(S1, S0, Added),
    subtract_eq_(S0, S1, Deleted).

unexplained_(Model, Args, Added, Deleted, UAdd, UDel) :-
    bound_model_(Model, Args, action_model(_, _, _, Add, Del)),
    exclude(explained_(Add), Added, UAdd),
    exclude(explained_(Del), Deleted, UDel).

%   L is one of Effects or a spatial literal of a tool T with spatial_of(T) there.
explained_(Effects, L) :-
    (   memberchk(L, Effects)
    ->  true
    ;   member(spatial_of(T), Effects),
        tool_literal_kind(T, L, spatial)
    ->  true
    ).

new_model_(Skill, Args, S0, Model, Names, frame(Tool, Target, Context), UAdd, UDel,
           new(NewModel, Example)) :-
    action_model_instance(Model, Args, _, Pre0, Add0, Del0),
    exclude(is_schema_, Add0, Add1),
    exclude(is_schema_, Del0, Del1),
    include(kind_(Tool, structural), S0, Structural),
    include(kind_(Tool, catalogue), S0, Catalogue),
    include(spatial_wrt_(Tool, [Target, Context]), S0, Spatial),
    include(kind_(Tool, other), UDel, Task),
    append([Structural, Spatial, Task], Body),
    append([Structural, Catalogue, Spatial, Task], ExampleBody),
    list_conj_(ExampleBody, BodyConj),
    Example = (tool_pose(Tool, Target, Context) :- BodyConj),
    append(Pre0, Body, Pre1),
    append(Add1, UAdd, Add2),
    append(Del1, UDel, Del2),
    maplist(dedupe_eq_, [Pre1, Add2, Del2], [Pre, Add, Del]),
    subtract_eq_(Args, [Tool, Target, Context], Extra),
    extra_params_(Extra, Model, Args, ExtraParams),
    Objects = [Tool-tool, Target-target, Context-site|ExtraParams],
    effect_name_(UAdd, UDel, EffectName),
    new_model_name_(Names, Skill, EffectName, Name),
    variablise_(Objects, action_model(Name, Objects, Pre, Add, Del), NewModel).

effect_name_(UAdd, UDel, Name) :-
    (   UAdd = [A|_]
    ->  functor(A, Name, _)
    ;   UDel = [D|_],
        functor(D, DName, _),
        atom_concat(not_, DName, Name)
    ).

is_schema_(spatial_of(_)).

kind_(Tool, Kind, L) :-
    tool_literal_kind(Tool, L, Kind).

%   A spatial literal of Tool whose other arguments are all among Relata.
spatial_wrt_(Tool, Relata, L) :-
    tool_literal_kind(Tool, L, spatial),
    L =.. [_, _|Others],
    forall(member(O, Others), memberchk(O, Relata)).

extra_params_([], _, _, []).
extra_params_([A|As], Model, Args, [A-Type|Ps]) :-
    bound_model_(Model, Args, action_model(_, Params, _, _, _)),
    memberchk(A-Type, Params),
    extra_params_(As, Model, Args, Ps).

%   Every case's names of learned actions (hook predicate learned_action_names/2).
ontology_action_names_(Names) :-
    findall(Ns, ontology_holds(learned_action_names(_, Ns)), Nss),
    append(Nss, Names).

new_model_name_(Names, Skill, Effect, Name) :-
    (   memberchk(name(Skill, Effect, Name0), Names)
    ->  Name = Name0
    ;   atomic_list_concat([Skill, '_for_', Effect], Name)
    ).

%   Replace each object constant of Objects (Name-Type) by one fresh variable.
variablise_(Objects, Term0, Term) :-
    pairs_keys_(Objects, Names),
    length(Names, N),
    length(Vars, N),
    pairs_from_(Names, Vars, Map),
    replace_atoms_(Term0, Map, Term).

pairs_keys_([], []).
pairs_keys_([K-_|Ps], [K|Ks]) :-
    pairs_keys_(Ps, Ks).

pairs_from_([], [], []).
pairs_from_([K|Ks], [V|Vs], [K-V|Ps]) :-
    pairs_from_(Ks, Vs, Ps).

replace_atoms_(T0, Map, T) :-
    (   atom(T0), memberchk(T0-V, Map)
    ->  T = V
    ;   compound(T0)
    ->  T0 =.. [F|Args0],
        maplist(replace_atoms_in_(Map), Args0, Args),
        T =.. [F|Args]
    ;   T = T0
    ).

replace_atoms_in_(Map, T0, T) :-
    replace_atoms_(T0, Map, T).

list_conj_([], true).
list_conj_([L], L) :- !.
list_conj_([L|Ls], (L, C)) :-
    list_conj_(Ls, C).

%   Order-preserving set difference and deduplication with ==.
subtract_eq_([], _, []).
subtract_eq_([X|Xs], Ys, Zs) :-
    (   member(Y, Ys), Y == X
    ->  Zs = Zs1
    ;   Zs = [X|Zs1]
    ),
    subtract_eq_(Xs, Ys, Zs1).

dedupe_eq_(Xs, Ys) :-
    dedupe_eq_(Xs, [], Ys).

dedupe_eq_([], _, []).
dedupe_eq_([X|Xs], Seen, Ys) :-
    (   member(S, Seen), S == X
    ->  Ys = Ys1
    ;   Ys = [X|Ys1]
    ),
    dedupe_eq_(Xs, [X|Seen], Ys1).

outcomes_result_(Outcomes, Result) :-
    (   memberchk(failed(Reason), Outcomes)
    ->  Result = no_model(Reason)
    ;   include([O]>>(O = matched(_, _, _)), Outcomes, Matched),
        findall(M-E, member(new(M, E), Outcomes), News),
        (   News = [_-Example|_]
        ->  pairs_keys_(News, NewModels),
            Result = models(Matched, NewModels, Example)
        ;   Result = no_model(nothing_to_learn)
        )
    ).
