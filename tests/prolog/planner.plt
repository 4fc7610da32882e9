:- begin_tests(planner).

:- use_module(library(lists)).
:- use_module('fixtures/demonstrations').

%   The innate and learned models of Case after its demonstration.
models_(Case, Models) :-
    fixture_demonstration(Case, Steps),
    innate_action_models(Case, Innate),
    observe_demonstration(Steps, Innate, models(_, New, _)),
    append(New, Innate, Models).

planned_(Case, State, Options, Result) :-
    models_(Case, Models),
    action_task_goal(Case, Goal),
    plan(State, Goal, Models, Options, Result).

%   S0 without the literals whose first argument is Tool.
without_(Tool, S0, S) :-
    exclude(about_(Tool), S0, S).

about_(Tool, L) :-
    L =.. [_, A|_],
    A == Tool.

test(hook_plan, Steps == [pick_up(hook_a2), position_tool(hook_a2, cube1, tube1),
                          pull_out(hook_a2, cube1, tube1)]) :-
    fixture_initial_state(hook, S0),
    planned_(hook, S0, [], plan(Steps)).

test(wedge_plan, Steps == [pick_up(wedge_a2), place(wedge_a2, door1, floor1),
                           hold_door(wedge_a2, door1, floor1)]) :-
    fixture_initial_state(wedge, S0),
    planned_(wedge, S0, [objects([floor1-site])], plan(Steps)).

test(wedge_site_must_be_named, R == no_plan(no_object_of_type(hold_door, site))) :-
    fixture_initial_state(wedge, S0),
    planned_(wedge, S0, [], R).

test(goal_already_true, R == plan([])) :-
    planned_(hook, [out_of_tube(cube1, tube1)], [], R).

test(no_object_satisfies_a_forced_stick,
     R == no_plan(no_object_satisfies(pull_out,
                                      [hook(hook_a5), handle_length(hook_a5, medium),
                                       hook_length(hook_a5, long),
                                       hook_width(hook_a5, wide),
                                       hook_side(hook_a5, right),
                                       hook_angle(hook_a5, right)]))) :-
    fixture_initial_state(hook, S0),
    planned_(hook, S0, [tool(hook_a5)], R).

test(best_object_fewest_failures_then_name,
     R == no_plan(no_object_satisfies(pull_out, [handle_length(hook_a1, medium)]))) :-
    fixture_initial_state(hook, S0),
    without_(hook_a2, S0, S),
    planned_(hook, S, [], R).

test(tie_break_by_name, Steps = [pick_up(hook_a0)|_]) :-
    fixture_initial_state(hook, S0),
    findall(L0, ( member(L, S0), L =.. [F, hook_a2|As], L0 =.. [F, hook_a0|As] ),
            Copy),
    append(S0, Copy, S),
    planned_(hook, S, [], plan(Steps)).

test(tool_on_the_table_needed, R == no_plan(depth_bound(6))) :-
    fixture_initial_state(hook, S0),
    subtract(S0, [on_table(hook_a2)], S),
    planned_(hook, S, [], R).

test(depth_bound, R == no_plan(depth_bound(2))) :-
    fixture_initial_state(hook, S0),
    planned_(hook, S0, [max_depth(2)], R).

test(no_model_achieves, R == no_plan(no_model_achieves([out_of_tube(cube1, tube1)]))) :-
    fixture_initial_state(hook, S0),
    innate_action_models(hook, Innate),
    plan(S0, [out_of_tube(cube1, tube1)], Innate, [], R).

test(innate_goal_without_tool_model, R == plan([pick_up(h)])) :-
    innate_action_models(hook, Ms),
    plan([gripper_empty, on_table(h), tool(h)], [holding(h)], Ms, [], R).

test(negative_precondition_blocks_a_tool,
     R == no_plan(no_object_satisfies(use, [not(stick(s))]))) :-
    innate_action_models(hook, Innate),
    Use = action_model(use, [T-tool, C-target, U-site],
                       [holding(T), not(stick(T)), in_tube(T, U)], [done(C, U)], []),
    plan([gripper_empty, on_table(s), tool(s), stick(s), in_tube(c, u)],
         [done(c, u)], [Use|Innate], [], R).

test(motion_step_achieves_the_spatial_literals,
     Added == [hook_down(hook_a2), behind(hook_a2, cube1),
               centred_on(hook_a2, cube1), in_tube(hook_a2, tube1)]) :-
    fixture_initial_state(hook, S0),
    models_(hook, Models),
    planned_(hook, S0, [], plan(Steps)),
    plan_transitions(S0, Steps, Models, [_, transition(_, Sa, Sb), _]),
    subtract(Sb, Sa, Added).

test(plan_valid) :-
    fixture_initial_state(hook, S0),
    models_(hook, Models),
    planned_(hook, S0, [], plan(Steps)),
    plan_valid(S0, [out_of_tube(cube1, tube1)], Steps, Models).

test(plan_invalid_without_first_step, fail) :-
    fixture_initial_state(hook, S0),
    models_(hook, Models),
    planned_(hook, S0, [], plan([_|Steps])),
    plan_valid(S0, [out_of_tube(cube1, tube1)], Steps, Models).

test(unknown_action, error(existence_error(action, fly/0))) :-
    plan_transitions([], [fly], [], _).

test(non_ground_state, error(type_error(ground_literal, on_table(_)))) :-
    plan([on_table(_)], [], [], [], _).

:- end_tests(planner).
