/*  The poke_cube case: ManiSkill3's PokeCube-v1 (worlds/poke_cube/, backend maniskill).
    A Panda grasps a peg (or another catalogued tool) and pokes a cube with it into the
    goal region, a disc 10 cm beyond the cube along +x (ManiSkill's evaluate() judges
    the goal; the robot is told the disc as reach_zone/4).

    Plain Prolog data loaded into this case's own module (case/1 names it), which sees
    the hook_like kind's module, the goal zone's (ontology/apparatus/goal_zone.pl) and
    the shared files.  The primitive facts come from the simulator's state
    (creative_py/backends/maniskill/episode.py).
*/

case(poke_cube).

%   The cube, the goal disc and the task: ontology/apparatus/goal_zone.pl, shared with
%   the other ManiSkill tabletop case.
case_apparatus(poke_cube, goal_zone).

case_tool_class(poke_cube, hook_like).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

task_roles(poke_cube, cube1, goal1).

case_goal(poke_cube, [in_zone(cube1, goal1)]).

case_skills(poke_cube, [pick_up, position_tool, push]).

%   push(T, C, Zone): push the held tool from the cube towards the goal's centre.
innate_skill(poke_cube, push,
             action_model(push, [T-tool, _C-target, _Zone-site],
                          [holding(T)],
                          [],
                          [spatial_of(T)])).

learned_action_names(poke_cube, [name(push, in_zone, poke_in)]).

                 /*******************************
                 *     POSE                     *
                 *******************************/

/*  The pose term poke_pose(Dx, Dy) (metres):
        Dx   the tool's tip (its far end's centre; a hook's prong centre) minus the
             cube's centre along x (- = behind the cube, on the robot's side; the goal
             lies along +x)
        Dy   the handle's axis minus the cube's centre along y
    The cube turns up to 30 degrees about z, so its half extent in x and y reaches
    0.027 m (cube_half 0.02 plus the clearance 0.01 covers it).
*/
%   behind: the tip behind the cube (-x), clear of it, within a band of 4 cm (farther
%   back, the push ends before the cube reaches the goal).
spatial_definition(poke_cube, behind(tool, target), poke_pose(Dx, _Dy),
                   [Dx =< -(cube_half + tip_half + clearance),
                    Dx >= -(cube_half + tip_half + clearance + band)]).
%   beyond: the tip past the cube (+x), clear of it.
spatial_definition(poke_cube, beyond(tool, target), poke_pose(Dx, _Dy),
                   [Dx >= cube_half + tip_half + clearance, Dx =< dx_max]).
%   in_line: the handle's axis within 1 cm of the cube's centre in y, so that the tip
%   meets the cube's face squarely.
spatial_definition(poke_cube, in_line(tool, target), poke_pose(_Dx, Dy),
                   [Dy >= -align, Dy =< align]).
%   beside: the handle clear of the cube on its right (-y).
spatial_definition(poke_cube, beside(tool, target), poke_pose(_Dx, Dy),
                   [Dy =< -(cube_half + handle_half + clearance), Dy >= -dy_room]).
%   across: the handle clear of the cube on its left (+y).
spatial_definition(poke_cube, across(tool, target), poke_pose(_Dx, Dy),
                   [Dy >= cube_half + handle_half + clearance, Dy =< dy_room]).

pose_domain(poke_cube, poke_pose(Dx, Dy),
            [Dx >= -dx_max, Dx =< dx_max, Dy >= -dy_room, Dy =< dy_room]).

geometry_default(poke_cube, cube_half, 0.02, 'half the cube side (ManiSkill: 4 cm cube)').
geometry_default(poke_cube, tip_half, 0.0, 'half the prong along x (a stick: its tip is its end face)').
geometry_default(poke_cube, handle_half, 0.025, 'half the handle width').
geometry_default(poke_cube, clearance, 0.01, 'clearance between the tool and the turned cube').
geometry_default(poke_cube, band, 0.04, 'width of the band behind the cube the tip lies in, m').
geometry_default(poke_cube, align, 0.01, 'how far the handle axis may lie off the cube centre in y, m').
geometry_default(poke_cube, dx_max, 0.12, 'bound of Dx either side of the cube').
geometry_default(poke_cube, dy_room, 0.09, 'bound of Dy either side of the cube').

geometry_value(poke_cube, tip_half, Tool, _Target, _G, V) :-
    nonvar(Tool),
    hook_width_m(Tool, W),
    V is W / 2.
geometry_value(poke_cube, handle_half, Tool, _Target, _G, V) :-
    nonvar(Tool),
    handle_width_m(Tool, W),
    V is W / 2.

%   No reach relation: whether a tool reaches the far cube is the physics' answer.
reach_definition(poke_cube, poke_pose(_, _), []).

relative_pose(poke_cube, Tool, Target, _G, poke_pose(Dx, Dy)) :-
    tip_position(Tool, TX, _, _),
    tool_axis_y(Tool, AY),
    pose(Target, CX, CY, _, _),
    Dx is TX - CX,
    Dy is AY - CY.

%   pose_target: place(X, Y, Heading): the tip's world x, the handle axis's world y, the
%   handle along +x.
pose_target(poke_cube, poke_pose(Dx, Dy), Target, _G, place(X, Y, 0.0)) :-
    pose(Target, CX, CY, _, _),
    X is CX + Dx,
    Y is CY + Dy.

                 /*******************************
                 *     SIZING A NEW TOOL        *
                 *******************************/

%   A new tool's handle is long enough to push the cube from behind into the far goal.
size_constraint(stick, reach_zone(_, _, _, _), [handle_length >= min_handle_m]).
size_constraint(hook, reach_zone(_, _, _, _), [handle_length >= min_handle_m]).

size_parameter(min_handle_m, 0.30,
               'a handle long enough to push the cube into the far goal').
