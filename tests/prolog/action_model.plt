:- begin_tests(action_model).

:- use_module(library(lists)).
:- use_module(library(apply)).

model_names_(Models, Names) :-
    maplist([action_model(N, _, _, _, _), N]>>true, Models, Names).

pull_out_model_(action_model(pull_out, [T-tool, C-target, U-site],
                             [holding(T), hook(T), in_tube(T, U), behind(T, C),
                              not(hook_flat(T)), in_tube(C, U)],
                             [out_of_tube(C, U)], [in_tube(C, U)])).

test(innate_hook_skills, Names == [pick_up, position_tool, pull]) :-
    innate_action_models(hook, Ms),
    model_names_(Ms, Names).

test(innate_wedge_skills, Names == [pick_up, place, release_door]) :-
    innate_action_models(wedge, Ms),
    model_names_(Ms, Names).

test(unknown_case, error(existence_error(case, kitchen))) :-
    innate_action_models(kitchen, _).

test(task_goals, [G1, G2] == [[out_of_tube(cube1, tube1)], [door_held(door1)]]) :-
    action_task_goal(hook, G1),
    action_task_goal(wedge, G2).

test(motion_skills, Names == [position_tool]) :-
    innate_action_models(hook, Ms),
    include([M]>>action_motion_tool(M, _), Ms, Motions),
    model_names_(Motions, Names).

test(not_a_model, error(type_error(action_model, foo(1)))) :-
    must_be_action_model(foo(1)).

test(bad_parameter, error(domain_error(action_parameter, x-robot))) :-
    must_be_action_model(action_model(a, [x-robot], [], [], [])).

test(instance, [Name, Pre] == [pick_up, [gripper_empty, on_table(hook_a2)]]) :-
    innate_action_models(hook, [PickUp|_]),
    action_model_instance(PickUp, [hook_a2], Name, Pre, _, _).

test(instance_arity, error(domain_error(arguments_of(pick_up), [a, b]))) :-
    innate_action_models(hook, [PickUp|_]),
    action_model_instance(PickUp, [a, b], _, _, _, _).

test(literal_kinds, Kinds == [structural, spatial, other, robot, spatial, other,
                              structural, catalogue]) :-
    maplist([L, K]>>tool_literal_kind(hook_a2, L, K),
            [handle_length(hook_a2, medium), behind(hook_a2, cube1),
             in_tube(cube1, tube1), gripper_empty, not(hook_down(hook_a2)),
             hook(hook_a1), object(hook_a2), handle_length_m(hook_a2, 0.35)],
            Kinds).

test(literal_kind_of_a_model_variable, [K1, K2] == [spatial, other]) :-
    tool_literal_kind(T, in_tube(T, _), K1),
    tool_literal_kind(T, in_tube(_, T), K2).

test(tool_model) :-
    pull_out_model_(M),
    action_tool_model(M, T),
    M = action_model(_, [T1-tool|_], _, _, _),
    T == T1.

test(a_model_needing_only_a_pose_is_a_tool_model) :-
    M = action_model(poke_in, [T-tool, C-target, Z-site],
                     [holding(T), out_of_zone(C, Z), behind(T, C)], [in_zone(C, Z)], []),
    action_tool_model(M, X),
    X == T.

test(innate_models_are_not_tool_models, Tools == []) :-
    innate_action_models(hook, Ms),
    include([M]>>action_tool_model(M, _), Ms, Tools).

test(compile_motion_for_a_learned_model,
     P =@= action_model(position_tool, [T-tool, C-target, U-site],
                        [holding(T), in_tube(C, U)],
                        [in_tube(T, U), behind(T, C)], [hook_flat(T)])) :-
    innate_action_models(hook, Ms),
    pull_out_model_(L),
    action_models_compile([L|Ms], Cs),
    model_names_(Cs, [pull_out, pick_up, pull, position_tool]),
    last(Cs, P).

test(motion_without_purpose_is_dropped, Names == [pick_up, pull]) :-
    innate_action_models(hook, Ms),
    action_models_compile(Ms, Cs),
    model_names_(Cs, Names).

test(two_purposes, [N1, N2, D1, D2] =@= [position_tool_for_pull_out,
                                         position_tool_for_push_in,
                                         [hook_flat(T1), in_front(T1, C1)],
                                         [in_tube(T2, U2), behind(T2, C2)]]) :-
    innate_action_models(hook, Ms),
    pull_out_model_(L1),
    L2 = action_model(push_in, [T-tool, C-target, U-site],
                      [hook(T), in_front(T, C)], [deep(C, U)], []),
    action_models_compile([L1, L2|Ms], Cs),
    reverse(Cs, [action_model(N2, [T2-tool, C2-target, U2-site], _, _, D2),
                 action_model(N1, [T1-tool, C1-target, _-site], _, _, D1)|_]).

test(objects, Os == [cube1-target, floor1-site, hook_a1-tool, medium-value,
                     tube1-site]) :-
    innate_action_models(hook, Ms),
    action_objects(Ms, [on_table(hook_a1), tool(hook_a1), in_tube(hook_a1, tube1),
                        handle_length(hook_a1, medium), in_tube(cube1, tube1)],
                   [floor1-site], Os).

test(objects_need_ground_literals, error(type_error(ground_literal, on_table(_)))) :-
    action_objects([], [on_table(_)], [], _).

:- end_tests(action_model).
