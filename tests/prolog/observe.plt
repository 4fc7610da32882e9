:- begin_tests(observe).

:- use_module(library(lists)).
:- use_module('fixtures/demonstrations').

observed_(Case, Options, Result) :-
    fixture_demonstration(Case, Steps),
    innate_action_models(Case, Models),
    observe_demonstration(Steps, Models, Options, Result).

test(hook_matched_steps, Matched == [matched(1, pick_up, [hook_a2]),
                                     matched(2, position_tool,
                                             [hook_a2, cube1, tube1])]) :-
    observed_(hook, [], models(Matched, _, _)).

test(hook_new_model,
     Model =@= action_model(pull_out, [T-tool, C-target, U-site],
                            [holding(T), tool(T), hook_like(T), hook(T),
                             handle_length(T, medium), handle_width(T, thick),
                             hook_length(T, long), hook_width(T, wide),
                             hook_side(T, right), hook_angle(T, right),
                             in_tube(T, U), behind(T, C), centred_on(T, C),
                             hook_down(T), in_tube(C, U)],
                            [out_of_tube(C, U)],
                            [in_tube(T, U), in_tube(C, U)])) :-
    observed_(hook, [goal([out_of_tube(cube1, tube1)])], models(_, [Model], _)).

test(hook_example,
     Example == (tool_pose(hook_a2, cube1, tube1) :-
                    tool(hook_a2), hook_like(hook_a2), hook(hook_a2),
                    handle_length(hook_a2, medium), handle_width(hook_a2, thick),
                    hook_length(hook_a2, long), hook_width(hook_a2, wide),
                    hook_side(hook_a2, right), hook_angle(hook_a2, right),
                    in_tube(hook_a2, tube1), behind(hook_a2, cube1),
                    centred_on(hook_a2, cube1), hook_down(hook_a2),
                    in_tube(cube1, tube1))) :-
    observed_(hook, [], models(_, _, Example)).

test(wedge_new_model,
     Model =@= action_model(hold_door, [W-tool, D-target, _-site],
                            [door_open(D), object(W), block(W),
                             shape(W, triangular_prism), block_length(W, long),
                             block_width(W, wide), block_height(W, low),
                             mechanical_advantage(W, above_one),
                             near(W, D), far_from_hinge(W, D), tip_towards(W, D)],
                            [door_held(D)], [])) :-
    observed_(wedge, [goal([door_held(door1)])], models(_, [Model], _)).

test(wedge_example_head, Head == tool_pose(wedge_a2, door1, floor1)) :-
    observed_(wedge, [], models(_, _, (Head :- _))).

test(goal_not_reached, R == no_model(goal_not_reached([door_held(door1)]))) :-
    fixture_demonstration(wedge, [S1, S2, _]),
    Two = [S1, S2],
    innate_action_models(wedge, Ms),
    observe_demonstration(Two, Ms, [goal([door_held(door1)])], R).

test(nothing_to_learn, R == no_model(nothing_to_learn)) :-
    fixture_demonstration(hook, [PickUp|_]),
    innate_action_models(hook, Ms),
    observe_demonstration([PickUp], Ms, R).

test(empty, R == no_model(empty_demonstration)) :-
    innate_action_models(hook, Ms),
    observe_demonstration([], Ms, R).

test(unknown_skill, R == no_model(unknown_skill(1, fly))) :-
    innate_action_models(hook, Ms),
    observe_demonstration([step(fly, [], [a], [b])], Ms, R).

test(precondition_not_observed,
     R == no_model(precondition_not_observed(1, pick_up, [gripper_empty]))) :-
    innate_action_models(hook, Ms),
    observe_demonstration([step(pick_up, [h], [on_table(h)], [holding(h)])], Ms, R).

test(a_step_without_change_is_explained, R == no_model(nothing_to_learn)) :-
    innate_action_models(hook, Ms),
    observe_demonstration([step(pick_up, [h], [on_table(h)], [on_table(h)])], Ms, R).

test(no_tool_for_step, R == no_model(no_tool_for_step(1, release_door))) :-
    innate_action_models(wedge, Ms),
    observe_demonstration([step(release_door, [door1], [door_open(door1)],
                                [door_open(door1), door_held(door1)])], Ms, R).

test(change_during_a_motion_gets_a_derived_name,
     [Name, Add, Del] =@= [position_tool_for_out_of_tube, [out_of_tube(C, U)],
                           [in_tube(C, U)]]) :-
    innate_action_models(hook, Ms),
    S0 = [holding(h), hook(h), in_tube(c, u)],
    S1 = [holding(h), hook(h), behind(h, c), out_of_tube(c, u)],
    observe_demonstration([step(position_tool, [h, c, u], S0, S1)], Ms,
                          models([], [action_model(Name, [_-tool, C-target, U-site],
                                                   _, Add, Del)], _)).

test(spatial_literals_going_false_in_a_pull_are_explained,
     [Add, Del] =@= [[out_of_tube(C, U), hook_flat(T)], [in_tube(T, U), in_tube(C, U)]]) :-
    innate_action_models(hook, Ms),
    S0 = [holding(h), hook(h), in_tube(h, u), behind(h, c), in_tube(c, u)],
    S1 = [holding(h), hook(h), out_of_tube(c, u), hook_flat(h)],
    observe_demonstration([step(pull, [h, c, u], S0, S1)], Ms,
                          models([], [action_model(pull_out, [T-tool, C-target, U-site],
                                                   _, Add, Del)], _)).

test(transition, [A, D] == [[holding(h)], [gripper_empty, on_table(h)]]) :-
    innate_action_models(hook, [PickUp|_]),
    observe_transition(step(pick_up, [h], [gripper_empty, on_table(h)], [holding(h)]),
                       PickUp, A, D).

test(bad_step, error(type_error(demonstration_step, step(pick_up, h, [], [])))) :-
    innate_action_models(hook, Ms),
    observe_demonstration([step(pick_up, h, [], [])], Ms, _).

test(non_ground_state, error(type_error(demonstration_step, _))) :-
    innate_action_models(hook, Ms),
    observe_demonstration([step(pick_up, [h], [on_table(_)], [])], Ms, _).

test(catalogue_numbers_go_to_the_example_only,
     [Body, Pre] =@= [(hook(h), handle_length_m(h, 0.35), behind(h, c), in_tube(c, u)),
                      [holding(T), hook(T), behind(T, C), in_tube(C, U)]]) :-
    innate_action_models(hook, Ms),
    S0 = [holding(h), hook(h), handle_length_m(h, 0.35), behind(h, c), in_tube(c, u)],
    S1 = [holding(h), hook(h), handle_length_m(h, 0.35), behind(h, c),
          out_of_tube(c, u)],
    observe_demonstration([step(pull, [h, c, u], S0, S1)], Ms,
                          models([], [action_model(pull_out, [T-tool, C-target, U-site],
                                                   Pre, _, _)],
                                 (_ :- Body))).

:- end_tests(observe).
