/*  The pull_cube_tool case: ManiSkill3's PullCubeTool-v1 (worlds/pull_cube_tool/,
    backend maniskill).  A Panda grasps an L-shaped tool and pulls a cube lying out of
    its reach into the goal region, a disc about the robot base (ManiSkill's
    evaluate() judges the goal; the robot is told the disc as reach_zone/4).

    Plain Prolog data loaded into this case's own module (case/1 names it), which sees
    the hook_like kind's module, the goal zone's (ontology/apparatus/goal_zone.pl) and
    the shared files.  The primitive facts come from the simulator's state
    (creative_py/backends/maniskill/episode.py).
*/

case(pull_cube_tool).

%   The cube, the goal disc and the task: ontology/apparatus/goal_zone.pl, shared with
%   the other ManiSkill tabletop case.
case_apparatus(pull_cube_tool, goal_zone).

case_tool_class(pull_cube_tool, hook_like).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

task_roles(pull_cube_tool, cube1, zone1).

case_goal(pull_cube_tool, [in_zone(cube1, zone1)]).

case_skills(pull_cube_tool, [pick_up, position_tool, pull]).

%   pull(T, C, Zone): draw the held tool back along -x, towards the robot.
innate_skill(pull_cube_tool, pull,
             action_model(pull, [T-tool, _C-target, _Zone-site],
                          [holding(T)],
                          [],
                          [spatial_of(T)])).

learned_action_names(pull_cube_tool, [name(pull, in_zone, pull_in)]).

                 /*******************************
                 *     POSE                     *
                 *******************************/

/*  The pose term pull_pose(Dx, Dy) (metres):
        Dx   the prong's centre minus the cube's centre along x (+ = behind, away from
             the robot)
        Dy   the handle's axis minus the cube's centre along y
    The cube turns up to 30 degrees about z, so its half extent in x and y reaches
    0.027 m (cube_half 0.02 plus the clearance 0.012 covers it).
*/
%   behind: the prong's centre behind the cube (+x), its front face clear of it, within
%   a band of 4 cm (farther back, the prong meets the cube late in the pull).
spatial_definition(pull_cube_tool, behind(tool, target), pull_pose(Dx, _Dy),
                   [Dx >= cube_half + prong_half + clearance,
                    Dx =< cube_half + prong_half + clearance + 2*band]).
spatial_definition(pull_cube_tool, in_front(tool, target), pull_pose(Dx, _Dy),
                   [Dx =< -(cube_half + prong_half + clearance), Dx >= -dx_max]).
%   beside: the handle clear of the cube on its right (-y), within a band of 2 cm, so
%   that the prong reaches across the cube.
spatial_definition(pull_cube_tool, beside(tool, target), pull_pose(_Dx, Dy),
                   [Dy =< -(cube_half + handle_half),
                    Dy >= -(cube_half + handle_half + clearance + band)]).
%   across: the handle clear of the cube on its left (+y).
spatial_definition(pull_cube_tool, across(tool, target), pull_pose(_Dx, Dy),
                   [Dy >= cube_half + handle_half + clearance, Dy =< dy_room]).

pose_domain(pull_cube_tool, pull_pose(Dx, Dy),
            [Dx >= -dx_max, Dx =< dx_max, Dy >= -dy_room, Dy =< dy_room]).

geometry_default(pull_cube_tool, cube_half, 0.02, 'half the cube side (ManiSkill: 4 cm cube)').
geometry_default(pull_cube_tool, prong_half, 0.025, 'half the prong thickness along x').
geometry_default(pull_cube_tool, handle_half, 0.025, 'half the handle width').
geometry_default(pull_cube_tool, clearance, 0.005, 'clearance between the prong or handle and the cube').
geometry_default(pull_cube_tool, band, 0.025, 'width of the band beside the cube the handle lies in, m').
geometry_default(pull_cube_tool, dx_max, 0.12, 'bound of Dx either side of the cube').
geometry_default(pull_cube_tool, dy_room, 0.09, 'bound of Dy either side of the cube').

geometry_value(pull_cube_tool, prong_half, Tool, _Target, _G, V) :-
    nonvar(Tool),
    (   hook_width_m(Tool, W),
        W > 0
    ->  true
    ;   handle_width_m(Tool, W)
    ),
    V is W / 2.
geometry_value(pull_cube_tool, handle_half, Tool, _Target, _G, V) :-
    nonvar(Tool),
    handle_width_m(Tool, W),
    V is W / 2.

%   No reach relation: whether a tool reaches the far cube is the physics' answer.
reach_definition(pull_cube_tool, pull_pose(_, _), []).

relative_pose(pull_cube_tool, Tool, Target, _G, pull_pose(Dx, Dy)) :-
    tip_position(Tool, TX, _, _),
    tool_axis_y(Tool, AY),
    pose(Target, CX, CY, _, _),
    Dx is TX - CX,
    Dy is AY - CY.

%   pose_target: place(X, Y, Heading): the prong centre's world x, the handle axis's
%   world y, the handle along +x.
pose_target(pull_cube_tool, pull_pose(Dx, Dy), Target, _G, place(X, Y, 0.0)) :-
    pose(Target, CX, CY, _, _),
    X is CX + Dx,
    Y is CY + Dy.

                 /*******************************
                 *     SIZING A NEW TOOL        *
                 *******************************/

%   A new tool's prong reaches across the cube from a handle beside it.
size_constraint(hook, reach_zone(_, _, _, _), [hook_length >= min_prong_m]).

size_parameter(min_prong_m, 0.04,
               'a prong reaching across the 4 cm cube from a handle beside it').
