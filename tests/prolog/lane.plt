:- begin_tests(lane).

:- use_module(library(lists)).
:- use_module(library(apply)).

%   The lane (ontology/apparatus/lane.pl) is written once for the two RoboToolBench lane
%   cases; each case keeps its goal, pose term, geometry defaults and sizing.  The
%   states below are facts recorded by real runs (trials.jsonl, a pulled trial of each
%   case), cut to the held tool's catalogue; the answers pinned here are those the
%   cases gave when each still held its own copy of the lane.

bring_state_([pose(cube1, 0.8214642400405502, 1.114153272442756e-05, 0.03549967226534155,
                   8.643919396700284e-06),
              size(cube1, 0.06634897490679625, 0.06246101700522045, 0.07),
              held(rake_a2),
              tip_position(rake_a2, 0.9397287368774414, -0.0006099325837567449,
                           0.09288652241230011),
              tool_roll(rake_a2, -0.0485541449859069),
              lane_start(lane1, 0.76989, 0.0, 0.15),
              lane_length_m(lane1, 0.25),
              lane_room_m(lane1, 0.3, 0.3),
              lane_goal(lane1, 0.6, 0.0),
              object_kind(rake_a2, hook),
              handle_length_m(rake_a2, 0.3251),
              handle_width_m(rake_a2, 0.0117),
              hook_length_m(rake_a2, 0.0209),
              hook_width_m(rake_a2, 0.0145),
              hook_side_is(rake_a2, left),
              hook_angle_deg(rake_a2, 93.1991)]).

dislodge_state_([pose(cube1, 1.2398858664103525, 0.20029311191011176, 0.0453307144234867,
                      -5.776453353301125e-05),
                 size(cube1, 0.06997949286762517, 0.06885439727754727, 0.07),
                 held(rake_a3),
                 tip_position(rake_a3, 1.2874661684036255, 0.1997397094964981,
                              0.0879128947854042),
                 tool_roll(rake_a3, -0.04857572945565749),
                 lane_start(lane1, 0.9000000000000001, 0.2, 0.065),
                 lane_length_m(lane1, 0.395),
                 lane_room_m(lane1, 0.11, 0.11),
                 lane_goal(lane1, 0.9000000000000001, 0.2),
                 object_kind(rake_a3, hook),
                 handle_length_m(rake_a3, 0.5),
                 handle_width_m(rake_a3, 0.01),
                 hook_length_m(rake_a3, 0.02),
                 hook_width_m(rake_a3, 0.01),
                 hook_side_is(rake_a3, left),
                 hook_angle_deg(rake_a3, 90.0)]).

%   close_geometry_(+Expected, +Actual): the same names in the same order, each value
%   within 1e-12 (Prolog arithmetic on the same floats: exact up to the last bit).
close_geometry_(Expected, Actual) :-
    maplist([N=E, N=A]>>(abs(E - A) =< 1.0e-12), Expected, Actual).

test(both_lane_cases_see_the_lane_after_their_kind) :-
    kb_module_scope(case_bring_cube, S1),
    assertion(S1 == [case_bring_cube, kind_hook_like, apparatus_lane, kb]),
    kb_module_scope(case_dislodge_cube, S2),
    assertion(S2 == [case_dislodge_cube, kind_hook_like, apparatus_lane, kb]).

test(each_lane_case_keeps_its_goal_and_pose_term) :-
    case_info(bring_cube, I1),
    assertion(I1 == case([pick_up, position_tool, pull], [at_goal(cube1, lane1)],
                         cube1, lane1, bring_pose)),
    case_info(dislodge_cube, I2),
    assertion(I2 == case([pick_up, position_tool, pull], [dislodged(cube1, lane1)],
                         cube1, lane1, dislodge_pose)),
    case_answer(learned_action_names(bring_cube, N1)),
    assertion(N1 == [name(pull, at_goal, pull_to_goal)]),
    case_answer(learned_action_names(dislodge_cube, N2)),
    assertion(N2 == [name(pull, dislodged, pull_out)]),
    case_missing_hooks(bring_cube, M1),
    assertion(M1 == []),
    case_missing_hooks(dislodge_cube, M2),
    assertion(M2 == []).

%   The lane's skills are the same models for both cases.
test(the_lane_s_skills_serve_both_cases) :-
    innate_action_models(bring_cube, Ms1),
    innate_action_models(dislodge_cube, Ms2),
    assertion(Ms1 =@= Ms2),
    Ms1 = [_, action_model(position_tool, _, Pre, _, _)|_],
    assertion(Pre = [holding(_), on_lane(_, _)]),
    case_answer(untestable_literals(bring_cube, U)),
    assertion(U = [on_lane(_, _)]).

%   With no facts each case's own defaults hold (the prong, the lane's length and
%   room differ).
test(each_lane_case_keeps_its_geometry_defaults) :-
    pose_geometry(bring_cube, _, _, [], G1),
    assertion(G1 == [box_half=0.035, prong_half=0.006, clearance=0.005, lane_length=0.12,
                     dy_room=0.1, dx_max=0.064, dx_min= -0.044, handle_half=0.005,
                     wall_clearance=0.003, dy_max=0.05, dy_min= -0.05, arm_reach_x=0.8,
                     dx_reach=1.0]),
    pose_geometry(dislodge_cube, _, _, [], G2),
    assertion(G2 == [box_half=0.035, prong_half=0.005, clearance=0.005,
                     lane_length=0.395, dy_room=0.05, dx_max=0.05, dx_min= -0.335,
                     handle_half=0.005, wall_clearance=0.003, dy_max=0.05, dy_min= -0.05,
                     arm_reach_x=0.8, dx_reach=1.0]).

test(bring_cube_reads_a_recorded_state_through_the_lane) :-
    bring_state_(F),
    abstract_state(bring_cube, F, A),
    assertion(A == [hook(rake_a2), hook_down(rake_a2), hook_like(rake_a2), tool(rake_a2),
                    behind(rake_a2, cube1), centred_on(rake_a2, cube1),
                    handle_length(rake_a2, medium), handle_width(rake_a2, thin),
                    hook_angle(rake_a2, right), hook_length(rake_a2, short),
                    hook_side(rake_a2, left), hook_width(rake_a2, wide),
                    on_lane(cube1, lane1), on_lane(rake_a2, lane1)]),
    pose_geometry(bring_cube, rake_a2, cube1, F, G),
    assertion(close_geometry_(
                  [box_half=0.03317475740615698, prong_half=0.00725, clearance=0.005,
                   lane_length=0.25, dy_room=0.1, dx_max=0.19117575995944977,
                   dx_min= -0.044324240040550224, handle_half=0.00585,
                   wall_clearance=0.003, dy_max=0.14113885846727556,
                   dy_min= -0.14116114153272444, arm_reach_x=0.8,
                   dx_reach=0.3036357599594498], G)),
    pose_numbers(bring_cube, rake_a2, F, P),
    assertion(P = bring_pose(_, _, _)),
    P = bring_pose(Dx, Dy, Roll),
    assertion(abs(Dx - 0.11826449683689122) =< 1.0e-12),
    assertion(abs(Dy - -0.0006210741164811725) =< 1.0e-12),
    assertion(Roll == -0.0485541449859069),
    pose_reachable(bring_cube, rake_a2, [behind(rake_a2, cube1)], F, R),
    assertion(R == reachable(bring_pose(0.1183, 0.0, 0.0))).

test(dislodge_cube_reads_a_recorded_state_through_the_lane) :-
    dislodge_state_(F),
    abstract_state(dislodge_cube, F, A),
    assertion(A == [hook(rake_a3), hook_down(rake_a3), hook_like(rake_a3), tool(rake_a3),
                    behind(rake_a3, cube1), centred_on(rake_a3, cube1),
                    handle_length(rake_a3, long), handle_width(rake_a3, thin),
                    hook_angle(rake_a3, right), hook_length(rake_a3, short),
                    hook_side(rake_a3, left), hook_width(rake_a3, wide),
                    on_lane(cube1, lane1), on_lane(rake_a3, lane1)]),
    pose_geometry(dislodge_cube, rake_a3, cube1, F, G),
    assertion(close_geometry_(
                  [box_half=0.03499173504650583, prong_half=0.005, clearance=0.005,
                   lane_length=0.395, dy_room=0.05, dx_max=0.050114133589647676,
                   dx_min= -0.33488586641035234, handle_half=0.005, wall_clearance=0.003,
                   dy_max=0.04670688808988825, dy_min= -0.04729311191011175,
                   arm_reach_x=0.8, dx_reach=0.06011413358964757], G)),
    pose_numbers(dislodge_cube, rake_a3, F, P),
    P = dislodge_pose(Dx, Dy, _),
    assertion(abs(Dx - 0.04758030199327301) =< 1.0e-12),
    assertion(abs(Dy - -0.0005534024136136517) =< 1.0e-12),
    pose_reachable(dislodge_cube, rake_a3, [behind(rake_a3, cube1)], F, R),
    assertion(R == reachable(dislodge_pose(0.0476, 0.0, 0.0))).

%   The goal literals stay the cases' own: the cube on the lane is neither at the goal
%   mark (bring_cube) nor out of the open end (dislodge_cube); moved there, it is.
test(each_lane_case_keeps_its_goal_literal) :-
    bring_state_(F1),
    assertion(\+ case_prove(bring_cube, at_goal(cube1, lane1), F1)),
    once(select(pose(cube1, _, _, Z1, Yaw1), F1, pose(cube1, 0.601, 0.002, Z1, Yaw1), F1g)),
    assertion(case_prove(bring_cube, at_goal(cube1, lane1), F1g)),
    dislodge_state_(F2),
    assertion(\+ case_prove(dislodge_cube, dislodged(cube1, lane1), F2)),
    once(select(pose(cube1, _, Y2, Z2, Yaw2), F2, pose(cube1, 0.902, Y2, Z2, Yaw2), F2g)),
    assertion(case_prove(dislodge_cube, dislodged(cube1, lane1), F2g)),
    catch(case_prove(bring_cube, dislodged(cube1, lane1), F2g), E, true),
    assertion(E = error(existence_error(case_hook(bring_cube), dislodged/2), _)).

%   The pose arithmetic every hook-like case shares (ontology/world.pl) and the prong's
%   half from the hook-like catalogue (ontology/kinds/hook_like.pl).
test(shared_pose_arithmetic) :-
    Yaw is pi / 2,
    once(kb_module_prove(kb, half_extent_x(b, H),
                         [size(b, 0.06, 0.02, 0.01), pose(b, 0.0, 0.0, 0.0, Yaw)])),
    assertion(abs(H - 0.01) =< 1.0e-12),
    once(kb_module_prove(kb, tip_relative_pose(t, b, Dx, Dy, R),
                         [tip_position(t, 1.0, 0.25, 0.1), tool_roll(t, 0.5),
                          pose(b, 0.75, 0.0, 0.0, 0.0)])),
    assertion(Dx-Dy-R == 0.25-0.25-0.5),
    once(kb_module_prove(kb, tip_pose_target(0.25, 0.25, b, X, Y),
                         [pose(b, 0.75, 0.0, 0.0, 0.0)])),
    assertion(X-Y == 1.0-0.25),
    once(kb_module_prove(kind_hook_like, prong_half_m(s, P1),
                         [handle_width_m(s, 0.012)])),
    assertion(P1 == 0.006),
    once(kb_module_prove(kind_hook_like, prong_half_m(h, P2),
                         [handle_width_m(h, 0.012), hook_width_m(h, 0.008)])),
    assertion(P2 == 0.004).

:- end_tests(lane).
