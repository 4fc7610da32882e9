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
case_extra_objects(bring_cube, []).
case_skills(bring_cube, [pick_up, position_tool, pull]).

%   position_tool(T, B, L): move the held tool over the cube to a pose relative to it;
%   pull(T, B, L): draw it back along -x towards the goal.
innate_skill(bring_cube, position_tool,
             action_model(position_tool, [T-tool, B-target, L-site],
                          [holding(T), on_lane(B, L)],
                          [spatial_of(T)],
                          [spatial_of(T)])).
innate_skill(bring_cube, pull,
             action_model(pull, [T-tool, _B-target, L-site],
                          [holding(T)],
                          [],
                          [on_lane(T, L), spatial_of(T)])).

learned_action_names(bring_cube, [name(pull, at_goal, pull_to_goal)]).
tool_acts_when(bring_cube, held).

%   The tool is always used on the lane, never tested by placing it elsewhere.
untestable_literals(bring_cube, [on_lane(_, _)]).

                 /*******************************
                 *     STATE                    *
                 *******************************/

primitive_predicate(lane_start/4).
primitive_predicate(lane_length_m/2).
primitive_predicate(lane_room_m/3).
primitive_predicate(lane_goal/3).

task_predicate(bring_cube, on_lane/2).
task_predicate(bring_cube, at_goal/2).

%   on_lane(?Object, ?Lane): an uncatalogued object (the cube) on the lane.
on_lane(B, L) :-
    lane_start(L, SX, SY, SZ),
    lane_length_m(L, D),
    lane_room_m(L, W, H),
    pose(B, X, Y, Z, _),
    \+ object_kind(B, _),
    X >= SX,
    X =< SX + D,
    abs(Y - SY) =< W / 2,
    abs(Z - SZ) =< H / 2.

%   at_goal(?Object, ?Lane): its centre within goal_tolerance_m (L1, in the plane) of
%   the goal: the benchmark's done() asks under 4 mm of L1 error.
at_goal(B, L) :-
    lane_goal(L, GX, GY),
    pose(B, X, Y, _, _),
    \+ object_kind(B, _),
    abs(X - GX) + abs(Y - GY) =< 0.004.

%   tool_in_use(?Case, ?Tool), proved on the state: a held tool whose tip is in the
%   lane's room has spatial literals.
tool_in_use(bring_cube, Tool) :-
    held(Tool),
    lane_start(L, SX, SY, SZ),
    lane_length_m(L, D),
    lane_room_m(L, W, H),
    tip_position(Tool, X, Y, Z),
    X >= SX,
    X =< SX + D,
    abs(Y - SY) =< W / 2,
    abs(Z - SZ) =< H / 2.

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

geometry_value(bring_cube, box_half, _, Target, _, V) :-
    nonvar(Target),
    size(Target, Sx, Sy, _),
    pose(Target, _, _, _, Yaw),
    V is (Sx * abs(cos(Yaw)) + Sy * abs(sin(Yaw))) / 2.
geometry_value(bring_cube, prong_half, Tool, _, _, V) :-
    nonvar(Tool),
    (   hook_width_m(Tool, W)
    ->  true
    ;   handle_width_m(Tool, W)
    ),
    V is W / 2.
geometry_value(bring_cube, lane_length, _, _, _, D) :-
    lane_length_m(_, D).
geometry_value(bring_cube, dx_max, _, Target, G, V) :-
    nonvar(Target),
    lane_start(L, SX, _, _),
    lane_length_m(L, D),
    pose(Target, X, _, _, _),
    memberchk(prong_half=PH, G),
    V is SX + D - X - PH.
geometry_value(bring_cube, dx_min, _, Target, G, V) :-
    nonvar(Target),
    lane_start(_, SX, _, _),
    pose(Target, X, _, _, _),
    memberchk(prong_half=PH, G),
    V is SX - X + PH.

geometry_value(bring_cube, handle_half, Tool, _, _, V) :-
    nonvar(Tool),
    handle_width_m(Tool, W),
    V is W / 2.
geometry_value(bring_cube, dy_max, _, Target, G, V) :-
    nonvar(Target),
    lane_start(L, _, LY, _),
    lane_room_m(L, W, _),
    pose(Target, _, Y, _, _),
    memberchk(handle_half=HH, G),
    memberchk(wall_clearance=C, G),
    V is LY - Y + W / 2 - HH - C.
geometry_value(bring_cube, dy_min, _, Target, G, V) :-
    nonvar(Target),
    lane_start(L, _, LY, _),
    lane_room_m(L, W, _),
    pose(Target, _, Y, _, _),
    memberchk(handle_half=HH, G),
    memberchk(wall_clearance=C, G),
    V is LY - Y - W / 2 + HH + C.

%   How far the held tool reaches (reach_definition/3, read only before a tool is
%   tried in a harder task): the prong's centre at most the handle's length beyond
%   arm_reach_x.
reach_definition(bring_cube, bring_pose(Dx, _Dy, _Roll), [Dx =< dx_reach]).

geometry_value(bring_cube, dx_reach, Tool, Target, G, V) :-
    nonvar(Tool),
    nonvar(Target),
    handle_length_m(Tool, Len),
    pose(Target, X, _, _, _),
    memberchk(arm_reach_x=R, G),
    V is R + Len - X.

%   The held tool's pose relative to the cube (proprioception and camera).
relative_pose(bring_cube, Tool, Target, _, bring_pose(Dx, Dy, Roll)) :-
    tip_position(Tool, TX, TY, _),
    tool_roll(Tool, Roll),
    pose(Target, X, Y, _, _),
    Dx is TX - X,
    Dy is TY - Y.

%   Where a pose puts the prong's centre (x, y) and the roll.
pose_target(bring_cube, bring_pose(Dx, Dy, Roll), Target, _, tip(X, Y, Roll)) :-
    pose(Target, BX, BY, _, _),
    X is BX + Dx,
    Y is BY + Dy.

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
