/*  The high-object case (RoboToolBench's HighObject: Gao et al., "VLMgineer", arXiv
    2507.12644): a cube lies on top of a tall shelf, out of the Panda's reach; a
    hook-like tool carried over the shelf's top puts its prong behind the cube and pulls
    it over the front edge, so that it falls into an open box between the shelf and the
    robot.  Everything the engine knows about this case is here, in its own module
    (case_high_object); the engine asks for it through the hook predicates of
    ontology/README.md.  Rules marked "proved on the state" take their primitive facts
    (pose/5, shelf_top/4, ...) from the state the engine hands over.

    The apparatus: a standing shelf (shelf1) whose top, at shelf_top/4's height,
    reaches along +x from its front edge (shelf_top_depth_m/2 deep); the room above
    the top is the passage the tool is carried through.  An open box (box1) stands in
    front of it, on the robot's side.
*/

case(high_object).
case_tool_class(high_object, hook_like).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

task_roles(high_object, cube1, shelf1).
case_goal(high_object, [in_box_below(cube1, shelf1)]).
case_extra_objects(high_object, []).
case_skills(high_object, [pick_up, position_tool, pull]).

%   position_tool(T, C, S): carry the held tool over the shelf's top to a pose
%   relative to the cube; pull(T, C, S): draw it back along -x.
innate_skill(high_object, position_tool,
             action_model(position_tool, [T-tool, C-target, S-site],
                          [holding(T), on_shelf_top(C, S)],
                          [spatial_of(T)],
                          [spatial_of(T)])).
innate_skill(high_object, pull,
             action_model(pull, [T-tool, _C-target, S-site],
                          [holding(T)],
                          [],
                          [over_shelf_top(T, S), spatial_of(T)])).

learned_action_names(high_object, [name(pull, in_box_below, pull_down)]).
tool_acts_when(high_object, held).

%   The tool is always used over the shelf's top, never tested elsewhere.
untestable_literals(high_object, [over_shelf_top(_, _)]).

                 /*******************************
                 *     STATE                    *
                 *******************************/

%   The standing shelf (scene body kind standing_shelf): its front edge's x, the
%   centre line's y, the top's z; its depth.  The open box (open_box): its centre's x
%   and y, its rim's z; its inner extent and its floor's top z.
primitive_predicate(shelf_top/4).
primitive_predicate(shelf_top_depth_m/2).
primitive_predicate(open_box_rim/4).
primitive_predicate(open_box_inner_m/5).

task_predicate(high_object, on_shelf_top/2).
task_predicate(high_object, in_box_below/2).

%   on_shelf_top(?Object, ?Shelf): an uncatalogued object lying on the shelf's top.
on_shelf_top(B, S) :-
    shelf_top(S, FX, _, Z),
    shelf_top_depth_m(S, D),
    pose(B, X, _, BZ, _),
    \+ object_kind(B, _),
    X >= FX,
    X =< FX + D,
    BZ >= Z - 0.01.

%   in_box_below(?Object, ?Shelf): the object lies inside an open box in front of the
%   shelf, below the box's rim.
in_box_below(B, S) :-
    shelf_top(S, FX, _, _),
    open_box_rim(Box, BX, BY, Rim),
    open_box_inner_m(Box, IX, IY, Floor, Rim),
    BX < FX,
    pose(B, X, Y, Z, _),
    \+ object_kind(B, _),
    abs(X - BX) =< IX / 2,
    abs(Y - BY) =< IY / 2,
    Z >= Floor,
    Z =< Rim.

%   tool_in_use(?Case, ?Tool), proved on the state: a held tool whose prong is above the
%   shelf's top has spatial literals.
tool_in_use(high_object, Tool) :-
    held(Tool),
    shelf_top(S, FX, _, Z),
    shelf_top_depth_m(S, D),
    tip_position(Tool, X, _, TZ),
    X >= FX,
    X =< FX + D,
    TZ >= Z,
    TZ =< Z + 0.20.

                 /*******************************
                 *     POSE                     *
                 *******************************/

/*  over_pose(Dx, Dy, Roll) (metres, metres, radians): the prong's centre minus the
    cube's centre along x and y, and the tool's roll about its handle (0 = prong down,
    +-pi/2 = flat).  Behind: the prong clears the cube (half its extent along x, half
    the prong, 5 mm); over_shelf_top: the prong between the top's front and back edge.
*/
spatial_definition(high_object, over_shelf_top(tool, context), over_pose(Dx, Dy, _),
                   [Dx =< dx_max, Dx >= dx_min, Dy =< dy_room, Dy >= -dy_room]).
spatial_definition(high_object, behind(tool, target), over_pose(Dx, _, _),
                   [Dx >= cube_half + prong_half + clearance, Dx =< dx_max]).
spatial_definition(high_object, in_front(tool, target), over_pose(Dx, _, _),
                   [Dx =< -(cube_half + prong_half + clearance), Dx >= dx_min]).
spatial_definition(high_object, centred_on(tool, target), over_pose(_, Dy, _),
                   [Dy =< 0.005, Dy >= -0.005]).
spatial_definition(high_object, hook_down(tool), over_pose(_, _, Roll),
                   [Roll =< 0.35, Roll >= -0.35]).
spatial_definition(high_object, hook_flat(tool), over_pose(_, _, Roll), [Roll >= 1.2]).
spatial_definition(high_object, hook_flat(tool), over_pose(_, _, Roll), [Roll =< -1.2]).

spatial_meaning(high_object, hook_down(tool), working_part_down(tool)).

pose_domain(high_object, over_pose(Dx, Dy, Roll),
            [Dx >= -0.40, Dx =< 0.40, Dy >= -dy_room, Dy =< dy_room,
             Roll >= -pi/2, Roll =< pi/2]).

geometry_default(high_object, cube_half, 0.025, 'half the cube extent along x (5 cm)').
geometry_default(high_object, prong_half, 0.006, 'half the prong thickness along the handle').
geometry_default(high_object, clearance, 0.005, 'clearance between prong and cube').
geometry_default(high_object, dy_room, 0.10, 'lateral bound of any pose').
geometry_default(high_object, deep_m, 0.035, 'how far behind the cube''s back the prong may go: deeper asks the arm to reach further than it can at the top''s height').
geometry_default(high_object, dx_max, 0.066, 'the deepest prong centre behind the cube''s centre').
geometry_default(high_object, dx_min, -0.09, 'front edge minus the cube centre, plus half the prong').
geometry_default(high_object, hand_reach_x, 0.64, 'the farthest x the Panda carries a forward-pointing gripper at the shelf top''s height (measured: 0.66 m; kept on the generous side, so that a pose is called unreachable only where the physics cannot reach it)').
geometry_default(high_object, reach_loss, 0.04, 'handle length behind the gripper: the grip offset').
geometry_default(high_object, dx_reach, 1.0, 'deepest prong centre the held tool reaches, minus the cube centre (1 m, no bound, when its handle is not known)').

%   The cube's extent along x from its perceived size and heading.
geometry_value(high_object, cube_half, _, Target, _, V) :-
    nonvar(Target),
    half_extent_x(Target, V).
geometry_value(high_object, prong_half, Tool, _, _, V) :-
    nonvar(Tool),
    prong_half_m(Tool, V).
geometry_value(high_object, dx_max, _, Target, G, V) :-
    nonvar(Target),
    shelf_top(S, FX, _, _),
    shelf_top_depth_m(S, D),
    pose(Target, X, _, _, _),
    memberchk(cube_half=CH, G),
    memberchk(prong_half=PH, G),
    memberchk(deep_m=Deep, G),
    V is min(FX + D - X - PH, CH + PH + Deep).
geometry_value(high_object, dx_min, _, Target, G, V) :-
    nonvar(Target),
    shelf_top(_, FX, _, _),
    pose(Target, X, _, _, _),
    memberchk(prong_half=PH, G),
    V is FX - X + PH.

%   How far the held tool reaches over the shelf's top (reach_definition/3, read only
%   before a tool is tried in a harder task): its prong's centre at most the handle's
%   length, less the grip offset and half the prong, beyond the farthest x the arm
%   carries the gripper to at the top's height.  Measured on the Panda (creative trial,
%   the benchmark's variant): a 0.40 m handle stops with the gripper at 0.66 m, short
%   of the cube; a 0.66 m one reaches behind it.
reach_definition(high_object, over_pose(Dx, _Dy, _Roll), [Dx =< dx_reach]).

geometry_value(high_object, dx_reach, Tool, Target, G, V) :-
    nonvar(Tool),
    nonvar(Target),
    handle_length_m(Tool, L),
    pose(Target, X, _, _, _),
    memberchk(hand_reach_x=H, G),
    memberchk(prong_half=PH, G),
    memberchk(reach_loss=Loss, G),
    V is H + L - Loss - PH - X.

%   The held tool's pose relative to the cube (proprioception and camera).
relative_pose(high_object, Tool, Target, _, over_pose(Dx, Dy, Roll)) :-
    tip_relative_pose(Tool, Target, Dx, Dy, Roll).

%   Where a pose puts the prong's centre (x, y) and the roll.
pose_target(high_object, over_pose(Dx, Dy, Roll), Target, _, tip(X, Y, Roll)) :-
    tip_pose_target(Dx, Dy, Target, X, Y).

                 /*******************************
                 *     SIZING A NEW TOOL        *
                 *******************************/

%   The handle reaches from where the arm can carry the gripper to behind a cube on
%   the shelf's top.
size_constraint(hook, shelf_top(_, FX, _, _),
                [handle_length >= FX - hand_reach_x + high_reach_margin_m]).
size_constraint(stick, shelf_top(_, FX, _, _),
                [handle_length >= FX - hand_reach_x + high_reach_margin_m]).

size_parameter(hand_reach_x, 0.64,
               'the farthest x the Panda carries a forward-pointing gripper at the shelf top''s height').
size_parameter(high_reach_margin_m, 0.20,
               'handle length beyond the front edge: to behind a cube 0.1 m deep (its half, the prong, 5 mm) and the grip offset').
