/*  The dislodge_cube case: RoboToolBench's DislodgeCube (VLMgineer, arXiv
    2507.12644; docs/robotoolbench.md).  A 7 cm cube lies 2 cm from the closed end of
    an L-shaped pipe beyond the Panda's reach; a hook-like tool is inserted over it,
    its prong dropped into the gap behind it, and the pull draws it out of the open
    end.  (The same lane facts and pose as bring_cube's, in this case's own module.)  Everything the engine knows about
    this case is here, in its own module (case_dislodge_cube); the engine asks for it
    through the hook predicates of ontology/README.md.

    The apparatus: the pipe's passage, a lane (scene body kind lane; the walls are
    boxes of the scene) along +x from its open end at lane_start/4's x for
    lane_length_m/2 metres, lane_room_m/3 wide and high, its open end's mark at
    lane_goal/3.  The cube (cube1) lies in it.
*/

case(dislodge_cube).
case_tool_class(dislodge_cube, hook_like).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

task_roles(dislodge_cube, cube1, lane1).
case_goal(dislodge_cube, [dislodged(cube1, lane1)]).

%   The lane, its perception, its task literal on_lane/2, the skills that work in it
%   (position_tool, pull) and its geometry rules are the lane's, written once in
%   ontology/apparatus/lane.pl and shared with the bring_cube case.
case_apparatus(dislodge_cube, lane).

learned_action_names(dislodge_cube, [name(pull, dislodged, pull_out)]).

                 /*******************************
                 *     STATE                    *
                 *******************************/

task_predicate(dislodge_cube, dislodged/2).

%   dislodged(?Object, ?Lane): its centre at most 3 mm past the open end: the
%   benchmark's done() along x (1 - (x - 0.9) / 0.34 > 0.99).
dislodged(B, L) :-
    lane_goal(L, GX, _),
    pose(B, X, _, _, _),
    \+ object_kind(B, _),
    X < GX + 0.003.

                 /*******************************
                 *     POSE                     *
                 *******************************/

/*  dislodge_pose(Dx, Dy, Roll) (metres, metres, radians): the prong's centre minus the
    cube's centre along the lane (+x) and across it (+y, the handle axis), and the
    tool's roll about its handle (0 = prong down, +-pi/2 = flat).  Behind: the prong
    clears the cube (half its extent along x, half the prong, 5 mm).
*/
spatial_definition(dislodge_cube, on_lane(tool, context), dislodge_pose(Dx, Dy, _),
                   [Dx =< dx_max, Dx >= dx_min, Dy =< dy_max, Dy >= dy_min]).
spatial_definition(dislodge_cube, behind(tool, target), dislodge_pose(Dx, _, _),
                   [Dx >= box_half + prong_half + clearance, Dx =< dx_max]).
spatial_definition(dislodge_cube, in_front(tool, target), dislodge_pose(Dx, _, _),
                   [Dx =< -(box_half + prong_half + clearance), Dx >= dx_min]).
spatial_definition(dislodge_cube, centred_on(tool, target), dislodge_pose(_, Dy, _),
                   [Dy =< 0.005, Dy >= -0.005]).
spatial_definition(dislodge_cube, hook_down(tool), dislodge_pose(_, _, Roll),
                   [Roll =< 0.35, Roll >= -0.35]).
spatial_definition(dislodge_cube, hook_flat(tool), dislodge_pose(_, _, Roll), [Roll >= 1.2]).
spatial_definition(dislodge_cube, hook_flat(tool), dislodge_pose(_, _, Roll), [Roll =< -1.2]).

spatial_meaning(dislodge_cube, hook_down(tool), working_part_down(tool)).

pose_domain(dislodge_cube, dislodge_pose(Dx, Dy, Roll),
            [Dx >= -lane_length, Dx =< lane_length, Dy >= -dy_room, Dy =< dy_room,
             Roll >= -pi/2, Roll =< pi/2]).

geometry_default(dislodge_cube, box_half, 0.035, 'half the cube extent along x (7 cm)').
geometry_default(dislodge_cube, prong_half, 0.005, 'half the prong thickness along the handle').
geometry_default(dislodge_cube, clearance, 0.005, 'clearance between prong and cube').
geometry_default(dislodge_cube, lane_length, 0.395, 'the passage''s length').
geometry_default(dislodge_cube, dy_room, 0.05, 'lateral bound of any pose').
geometry_default(dislodge_cube, dx_max, 0.05, 'lane end minus the cube centre, minus half the prong').
geometry_default(dislodge_cube, dx_min, -0.335, 'lane start minus the cube centre, plus half the prong').
geometry_default(dislodge_cube, handle_half, 0.005, 'half the handle width').
geometry_default(dislodge_cube, wall_clearance, 0.003, 'room kept between the handle and the lane''s side').
geometry_default(dislodge_cube, dy_max, 0.05, 'largest Dy keeping the handle inside the lane').
geometry_default(dislodge_cube, dy_min, -0.05, 'smallest Dy keeping the handle inside the lane').
geometry_default(dislodge_cube, arm_reach_x, 0.80, 'farthest x the Panda puts the butt end of a held tool low over the table: a 0.26 m handle reached 1.05 m (measured, see reach_definition)').
geometry_default(dislodge_cube, dx_reach, 1.0, 'farthest prong centre the held tool reaches, minus the cube centre (1 m, no bound, when its handle is not known)').

%   How far the held tool reaches (reach_definition/3, read only before a tool is
%   tried in a harder task): the prong's centre at most the handle's length beyond
%   arm_reach_x.
reach_definition(dislodge_cube, dislodge_pose(Dx, _Dy, _Roll), [Dx =< dx_reach]).

%   box_half, prong_half, lane_length, dx_max, dx_min, handle_half, dy_max, dy_min and
%   dx_reach come from the facts by the lane's geometry_value/6 rules
%   (ontology/apparatus/lane.pl).

%   The held tool's pose relative to the cube (proprioception and camera:
%   ontology/world.pl's tip_relative_pose/5).
relative_pose(dislodge_cube, Tool, Target, _, dislodge_pose(Dx, Dy, Roll)) :-
    tip_relative_pose(Tool, Target, Dx, Dy, Roll).

%   Where a pose puts the prong's centre (x, y) and the roll.
pose_target(dislodge_cube, dislodge_pose(Dx, Dy, Roll), Target, _, tip(X, Y, Roll)) :-
    tip_pose_target(Dx, Dy, Target, X, Y).

                 /*******************************
                 *     SIZING A NEW TOOL        *
                 *******************************/

%   The handle reaches from outside the pipe's open end (the hand stays out of it) to
%   behind a cube at the closed end, and no longer than the arm can carry along the
%   insertion and the pull.
size_constraint(hook, lane_start(_, X, _, _),
                [handle_length >= X + pipe_reach_margin_m,
                 handle_length =< X + pipe_carry_margin_m]).
size_constraint(stick, lane_start(_, X, _, _),
                [handle_length >= X + pipe_reach_margin_m,
                 handle_length =< X + pipe_carry_margin_m]).

%   The handle fits between the cube's centre line and the right wall: the cube's centre
%   lies 5 mm from the wall's inner face, and centred_on allows the handle 5 mm off it,
%   keeping wall_clearance (3 mm) from the wall: half the handle at most 7 mm.
size_constraint(hook, lane_room_m(_, _, _), [handle_width =< pipe_handle_max_m]).
size_constraint(stick, lane_room_m(_, _, _), [handle_width =< pipe_handle_max_m]).

size_parameter(pipe_handle_max_m, 0.012,
               'widest handle centred on a cube 5 mm from the right wall (2 mm spare)').
size_parameter(pipe_reach_margin_m, -0.42,
               'handle length beyond the open end''s x: the pipe''s 0.395 m passage, the hand''s 0.05 m clear of the open end, less the arm''s reach of 0.80 m, plus the open end''s 0.9 m (0.40 m was not carried in, 0.50 m was)').
size_parameter(pipe_carry_margin_m, -0.35,
               'longest handle the arm carries along the insertion and the pull, minus the open end''s x (0.55 m was carried)').
