:- module(planner,
          [ plan/5,                     % +State, +Goal, +Models, +Options, -Result
            plan_transitions/4,         % +State0, +Steps, +Models, -Transitions
            plan_valid/4                % +State, +Goal, +Steps, +Models
          ]).

/** <module> A STRIPS planner that chooses the tool

plan/5 searches forward, by iterative deepening, for the shortest sequence of actions
that makes every goal literal true.  The models are first compiled
(action_model:action_models_compile/2): each motion skill (position_tool, place)
becomes an ordinary action whose add effects are the spatial literals a learned
model's precondition needs, so a plan reads pick_up, position_tool, pull_out.

**Tool choice.**  A learned (tool) model has structural preconditions on its tool
argument.  For every tool model that adds a goal literal, each available tool object
is scored by the structural literals of the model it fails in the state.  The objects
that fail none are tried in turn, the model order first and then the standard order of
the object names (the documented tie-break: `hook_a2` before `hook_a3`), and the
first one with a plan within the depth bound wins; in its search every parameter of
type `tool` is that object.  If no object satisfies them the result is
`no_plan(no_object_satisfies(Model, Unsatisfied))` for the best object (fewest
failures, then model order, then name): the trigger for tool creation.

Objects and their types come from the state and the goal (action_model:
action_objects/4), plus the objects(List) option; a `site` that no literal names
(`floor1` in the wedge case) must be given there.
*/

:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(option)).
:- use_module(library(ordsets)).
:- use_module(library(error)).
:- use_module(action_model).

%!  plan(+State, +Goal, +Models, +Options, -Result) is det.
%
%   Result is plan(Steps), Steps a shortest list of ground actions Name(Args...)
%   that takes State (a list of ground literals) to a state holding every literal of
%   Goal, or no_plan(Reason) with Reason one of
%
%     - no_object_satisfies(ModelName, Unsatisfied): the goal needs the tool model
%       ModelName and no available object has its structural preconditions;
%       Unsatisfied are the ground literals the best object fails;
%     - no_object_of_type(ModelName, Type): the tool model ModelName needs an
%       object of Type (tool, target or site) and the state, goal and objects
%       option name none;
%     - no_model_achieves(Goal): no model adds any goal literal;
%     - depth_bound(MaxDepth): no plan of at most MaxDepth steps.
%
%   Options:
%     - max_depth(+D): the longest plan searched (default 6);
%     - objects(+List): extra Name-Type objects (e.g. [floor1-site]);
%     - tool(+T): consider only the tool T.
%
%       ?- innate_action_models(hook, Ms),
%          plan([gripper_empty, on_table(h), tool(h)], [holding(h)], Ms, [], R).
%       R = plan([pick_up(h)]).
%
%   @error type_error(ground_literal, L) if a state or goal literal is not ground.

plan(State, Goal, Models, Options, Result) :-
    must_be(list, State),
    must_be(list, Goal),
    must_be(list, Models),
    must_be(list, Options),
    maplist(must_be_ground_literal_, State),
    maplist(must_be_ground_literal_, Goal),
    option(max_depth(MaxDepth), Options, 6),
    must_be(nonneg, MaxDepth),
    option(objects(Extra), Options, []),
    append(State, Goal, Literals),
    action_objects(Models, Literals, Extra, Objects),
    action_models_compile(Models, Actions),
    sort(State, S0),
    include(object_of_type_(tool), Objects, ToolObjects0),
    pairs_keys(ToolObjects0, AllTools),
    (   option(tool(Tool), Options)
    ->  must_be(atom, Tool),
        Tools = [Tool]
    ;   Tools = AllTools
    ),
    (   holds_all_(Goal, S0)
    ->  Result = plan([])
    ;   include(relevant_tool_model_(Goal), Actions, ToolModels),
        ToolModels \== []
    ->  (   member(action_model(Name, Params, _, _, _), ToolModels),
            member(_-Type, Params),
            \+ memberchk(_-Type, Objects)
        ->  Result = no_plan(no_object_of_type(Name, Type))
        ;   tool_choice_(ToolModels, Tools, S0, Choices),
            plan_with_tools_(Choices, S0, Goal, Actions, Objects, MaxDepth,
                             Result)
        )
    ;   search_(S0, Goal, Actions, Objects, Tools, MaxDepth, Steps)
    ->  Result = plan(Steps)
    ;   include(adds_goal_literal_(Goal), Actions, [])
    ->  Result = no_plan(no_model_achieves(Goal))
    ;   Result = no_plan(depth_bound(MaxDepth))
    ).

must_be_ground_literal_(L) :-
    (   callable(L), ground(L)
    ->  true
    ;   type_error(ground_literal, L)
    ).

object_of_type_(Type, _-Type).

holds_all_(Goal, S) :-
    forall(member(G, Goal), memberchk(G, S)).

adds_goal_literal_(Goal, action_model(_, _, _, Add, _)) :-
    member(G, Goal),
    member(A, Add),
    \+ G \= A,
    !.

relevant_tool_model_(Goal, Model) :-
    action_tool_model(Model, _),
    adds_goal_literal_(Goal, Model).

%   tool_choice_(+ToolModels, +Tools, +S, -Choices): Choices is
%   satisfying(Pairs) (Pairs a list of Model-Tool to try in order) or
%   best(ModelName, Unsatisfied).
tool_choice_(ToolModels, Tools, S, Choices) :-
    findall(key(N, I, Tool)-result(Model, Tool, Failures),
            ( nth1(I, ToolModels, Model),
              member(Tool, Tools),
              structural_failures_(Model, Tool, S, Failures),
              length(Failures, N)
            ),
            Scored0),
    keysort(Scored0, Scored),
    findall(Model-Tool, member(key(0, _, _)-result(Model, Tool, _), Scored), Pairs),
    (   Pairs \== []
    ->  Choices = satisfying(Pairs)
    ;   Scored = [_-result(action_model(Name, _, _, _, _), _, Failures)|_]
    ->  Choices = best(Name, Failures)
    ;   ToolModels = [action_model(Name, _, _, _, _)|_],
        Choices = best(Name, [])
    ).

%   The structural literals of Model's tool, with the tool bound to Tool, that no
%   literal of S matches (committing to the first match of each, in order).
structural_failures_(Model, Tool, S, Failures) :-
    copy_term(Model, action_model(_, Params, Pre, _, _)),
    memberchk(Tool-tool, Params),
    include(structural_of_(Tool), Pre, Structural),
    foldl(match_or_fail_(S), Structural, Failures0, []),
    Failures = Failures0.

structural_of_(Tool, L) :-
    tool_literal_kind(Tool, L, structural).

match_or_fail_(S, L, Fs0, Fs) :-
    (   L = not(P)
    ->  (   \+ ( member(Q, S), \+ Q \= P )
        ->  Fs0 = Fs
        ;   Fs0 = [L|Fs]
        )
    ;   memberchk(L, S)
    ->  Fs0 = Fs
    ;   Fs0 = [L|Fs]
    ).

plan_with_tools_(best(Name, Failures), _, _, _, _, _,
                 no_plan(no_object_satisfies(Name, Failures))).
plan_with_tools_(satisfying(Pairs), S0, Goal, Actions, Objects, MaxDepth, Result) :-
    (   member(_-Tool, Pairs),
        search_(S0, Goal, Actions, Objects, [Tool], MaxDepth, Steps)
    ->  Result = plan(Steps)
    ;   Result = no_plan(depth_bound(MaxDepth))
    ).

%   search_(+S0, +Goal, +Actions, +Objects, +Tools, +MaxDepth, -Steps) is semidet.
%   Iterative deepening depth-first search; the first (shortest) plan found.
search_(S0, Goal, Actions, Objects, Tools, MaxDepth, Steps) :-
    between(0, MaxDepth, Depth),
    dfs_(Depth, S0, Goal, Actions, Objects, Tools, [S0], Steps),
    !.

dfs_(Depth, S, Goal, Actions, Objects, Tools, Visited, Steps) :-
    (   holds_all_(Goal, S)
    ->  Steps = []
    ;   Depth > 0,
        Depth1 is Depth - 1,
        member(Action, Actions),
        apply_action_(Action, S, Objects, Tools, Step, S1),
        \+ memberchk(S1, Visited),
        Steps = [Step|Steps1],
        dfs_(Depth1, S1, Goal, Actions, Objects, Tools, [S1|Visited], Steps1)
    ).

%   apply_action_(+Model, +S, +Objects, +Tools, -Step, -S1) is nondet: every ground
%   instance of Model applicable in S, with its tool parameters among Tools.
apply_action_(Model, S, Objects, Tools, Step, S1) :-
    copy_term(Model, action_model(Name, Params, Pre, Add, Del)),
    partition(is_negative_, Pre, Neg, Pos),
    match_all_(Pos, S),
    maplist(bind_param_(Objects, Tools), Params),
    forall(member(not(N), Neg), \+ memberchk(N, S)),
    effects_state_(Name, Add, Del, S, S1),
    pairs_keys(Params, Args),
    Step =.. [Name|Args].

is_negative_(not(_)).

match_all_([], _).
match_all_([L|Ls], S) :-
    member(L, S),
    match_all_(Ls, S).

bind_param_(Objects, Tools, P-Type) :-
    (   var(P)
    ->  member(P-Type, Objects)
    ;   true
    ),
    (   Type == tool
    ->  memberchk(P, Tools)
    ;   true
    ).

effects_state_(Name, Add, Del, S, S1) :-
    (   ground(Add-Del)
    ->  sort(Add, AddSet),
        sort(Del, DelSet),
        ord_subtract(S, DelSet, S2),
        ord_union(S2, AddSet, S1)
    ;   domain_error(ground_effects_of(Name), Add-Del)
    ).

%!  plan_transitions(+State0, +Steps, +Models, -Transitions) is semidet.
%
%   Transitions is a list of transition(Step, S0, S1), one per step of Steps
%   executed from State0 with the compiled Models (S0, S1 sorted lists of literals):
%   it tells the executor, for instance, which spatial literals a position_tool step
%   must achieve (S1 minus S0).  Fails if a step is not applicable in its state.
%
%       ?- innate_action_models(hook, Ms),
%          plan_transitions([gripper_empty, on_table(h)], [pick_up(h)], Ms, Ts).
%       Ts = [transition(pick_up(h), [gripper_empty, on_table(h)], [holding(h)])].
%
%   @error existence_error(action, Name/Arity) if a step names no model.

plan_transitions(State0, Steps, Models, Transitions) :-
    must_be(list, State0),
    must_be(list, Steps),
    maplist(must_be_ground_literal_, State0),
    maplist(must_be_ground_literal_, Steps),
    action_models_compile(Models, Actions),
    sort(State0, S0),
    foldl(transition_(Actions), Steps, Transitions, S0, _).

transition_(Actions, Step, transition(Step, S0, S1), S0, S1) :-
    Step =.. [Name|Args],
    length(Args, Arity),
    (   member(Model, Actions),
        Model = action_model(Name, Params, _, _, _),
        length(Params, Arity)
    ->  true
    ;   existence_error(action, Name/Arity)
    ),
    action_model_instance(Model, Args, _, Pre, Add, Del),
    partition(is_negative_, Pre, Neg, Pos),
    once(match_all_(Pos, S0)),
    forall(member(not(N), Neg), \+ memberchk(N, S0)),
    effects_state_(Name, Add, Del, S0, S1).

%!  plan_valid(+State, +Goal, +Steps, +Models) is semidet.
%
%   True if Steps can be executed from State with Models and reach every literal
%   of Goal.
%
%       ?- innate_action_models(hook, Ms),
%          plan_valid([gripper_empty, on_table(h)], [holding(h)], [pick_up(h)], Ms).
%       true.

plan_valid(State, Goal, Steps, Models) :-
    must_be(list, Goal),
    plan_transitions(State, Steps, Models, Transitions),
    (   last(Transitions, transition(_, _, S))
    ->  true
    ;   sort(State, S)
    ),
    holds_all_(Goal, S).
