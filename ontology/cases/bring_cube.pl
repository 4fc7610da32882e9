/*  The bring_cube case: RoboToolBench's BringCube (VLMgineer, arXiv 2507.12644;
    docs/robotoolbench.md).  A 7 cm cube lies on the table beyond the Panda's reach;
    a hook-like tool is carried over it, its prong dropped behind it, and the pull
    brings it back along -x onto the goal mark.  Everything the engine knows about
    this case is here, in its own module (case_bring_cube); the engine asks for it
    through the hook predicates of ontology/README.md.

    The apparatus: an open lane (scene body kind lane: no walls) along +x on the
    table, from lane_start/4's x for lane_length_m/2 metres, lane_room_m/3 wide and
    high, with the goal at lane_goal/3.  The cube (cube1) lies on it.
*/

case(bring_cube).
case_tool_class(bring_cube, hook_like).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

task_roles(bring_cube, cube1, lane1).
case_goal(bring_cube, [at_goal(cube1, lane1)]).

%   The lane, its perception, its task literal on_lane/2, the skills that work in it
%   (position_tool, pull) and its geometry rules are the lane's, written once in
%   ontology/apparatus/lane.pl and shared with the dislodge_cube case.
case_apparatus(bring_cube, lane).

learned_action_names(bring_cube, [name(pull, at_goal, pull_to_goal)]).

                 /*******************************
                 *     STATE                    *
                 *******************************/

task_predicate(bring_cube, at_goal/2).

%   at_goal(?Object, ?Lane): its centre within goal_tolerance_m (L1, in the plane) of
%   the goal: the benchmark's done() asks under 4 mm of L1 error.
at_goal(B, L) :-
    lane_goal(L, GX, GY),
    pose(B, X, Y, _, _),
    \+ object_kind(B, _),
    abs(X - GX) + abs(Y - GY) =< 0.004.

                 /*******************************
                 *     POSE                     *
                 *******************************/

/*  bring_pose(Dx, Dy, Roll) (metres, metres, radians): the prong's centre minus the
    cube's centre along the lane (+x) and across it (+y, the handle axis), and the
    tool's roll about its handle (0 = prong down, +-pi/2 = flat).  Behind: the prong
    clears the cube (half its extent along x, half the prong, 5 mm).
*/
spatial_definition(bring_cube, on_lane(tool, context), bring_pose(Dx, Dy, _),
                   [Dx =< dx_max, Dx >= dx_min, Dy =< dy_max, Dy >= dy_min]).
spatial_definition(bring_cube, behind(tool, target), bring_pose(Dx, _, _),
                   [Dx >= box_half + prong_half + clearance, Dx =< dx_max]).
spatial_definition(bring_cube, in_front(tool, target), bring_pose(Dx, _, _),
                   [Dx =< -(box_half + prong_half + clearance), Dx >= dx_min]).
spatial_definition(bring_cube, centred_on(tool, target), bring_pose(_, Dy, _),
                   [Dy =< 0.005, Dy >= -0.005]).
spatial_definition(bring_cube, hook_down(tool), bring_pose(_, _, Roll),
                   [Roll =< 0.35, Roll >= -0.35]).
spatial_definition(bring_cube, hook_flat(tool), bring_pose(_, _, Roll), [Roll >= 1.2]).
spatial_definition(bring_cube, hook_flat(tool), bring_pose(_, _, Roll), [Roll =< -1.2]).

spatial_meaning(bring_cube, hook_down(tool), working_part_down(tool)).

pose_domain(bring_cube, bring_pose(Dx, Dy, Roll),
            [Dx >= -lane_length, Dx =< lane_length, Dy >= -dy_room, Dy =< dy_room,
             Roll >= -pi/2, Roll =< pi/2]).

geometry_default(bring_cube, box_half, 0.035, 'half the cube extent along x (7 cm)').
geometry_default(bring_cube, prong_half, 0.006, 'half the prong thickness along the handle').
geometry_default(bring_cube, clearance, 0.005, 'clearance between prong and cube').
geometry_default(bring_cube, lane_length, 0.12, 'lane length').
geometry_default(bring_cube, dy_room, 0.10, 'lateral bound of any pose').
geometry_default(bring_cube, dx_max, 0.064, 'lane end minus the cube centre, minus half the prong').
geometry_default(bring_cube, dx_min, -0.044, 'lane start minus the cube centre, plus half the prong').
geometry_default(bring_cube, handle_half, 0.005, 'half the handle width').
geometry_default(bring_cube, wall_clearance, 0.003, 'room kept between the handle and the lane''s side').
geometry_default(bring_cube, dy_max, 0.05, 'largest Dy keeping the handle inside the lane').
geometry_default(bring_cube, dy_min, -0.05, 'smallest Dy keeping the handle inside the lane').
geometry_default(bring_cube, arm_reach_x, 0.80, 'farthest x the Panda puts the butt end of a held tool low over the table: a 0.26 m handle reached 1.05 m (measured, see reach_definition)').
geometry_default(bring_cube, dx_reach, 1.0, 'farthest prong centre the held tool reaches, minus the cube centre (1 m, no bound, when its handle is not known)').

%   How far the held tool reaches (reach_definition/3, read only before a tool is
%   tried in a harder task): the prong's centre at most the handle's length beyond
%   arm_reach_x.
reach_definition(bring_cube, bring_pose(Dx, _Dy, _Roll), [Dx =< dx_reach]).

%   box_half, prong_half, lane_length, dx_max, dx_min, handle_half, dy_max, dy_min and
%   dx_reach come from the facts by the lane's geometry_value/6 rules
%   (ontology/apparatus/lane.pl).

%   The held tool's pose relative to the cube (proprioception and camera:
%   ontology/world.pl's tip_relative_pose/5).
relative_pose(bring_cube, Tool, Target, _, bring_pose(Dx, Dy, Roll)) :-
    tip_relative_pose(Tool, Target, Dx, Dy, Roll).

%   Where a pose puts the prong's centre (x, y) and the roll.
pose_target(bring_cube, bring_pose(Dx, Dy, Roll), Target, _, tip(X, Y, Roll)) :-
    tip_pose_target(Dx, Dy, Target, X, Y).

                 /*******************************
                 *     SIZING A NEW TOOL        *
                 *******************************/

%   The handle reaches from where the arm holds it to behind a cube 0.05 m past the
%   lane's start, and is no longer than the arm carries back to the goal.
size_constraint(hook, lane_start(_, X, _, _),
                [handle_length >= X + lane_reach_margin_m,
                 handle_length =< X + lane_carry_margin_m]).
size_constraint(stick, lane_start(_, X, _, _),
                [handle_length >= X + lane_reach_margin_m,
                 handle_length =< X + lane_carry_margin_m]).

size_parameter(lane_reach_margin_m, -0.68,
               'handle length beyond the lane start''s x: the cube 0.05 m past it, the prong 0.05 m behind the cube, less the arm''s reach of 0.80 m, plus 0.02 m').
size_parameter(lane_carry_margin_m, -0.61,
               'longest handle beyond the lane start''s x that the arm carries back to the goal: 0.34 m at the benchmark''s cube (0.26-0.40 m measured, 0.36-0.40 m sometimes found no posture, 0.45 m never)').
