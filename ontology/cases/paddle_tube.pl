/*  The paddle case: pull a cube out of a closed tube with a paddle, its blade upright
    behind the cube.  The hook case's apparatus (worlds/paddle_tube is the hook world
    with paddles), a tool kind no paper case has (ontology/kinds/paddle.pl).  The
    engine asks for everything here through the hook predicates of ontology/README.md.

    Plain Prolog data loaded into this case's own module (case_paddle_tube) by
    knowledge:load_ontology/1.  Rules marked "proved on the state" take their primitive
    facts from the state the engine hands over.  The tube is the hook case's, written
    once in ontology/apparatus/tube.pl (case_apparatus/2 below): its perception, task
    literals, skills, geometry rules and margins.
*/

case(paddle_tube).

case_tool_class(paddle_tube, paddle).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

task_roles(paddle_tube, cube1, tube1).

case_goal(paddle_tube, [out_of_tube(cube1, tube1)]).

%   The tube, its perception, its task literals (in_tube/2, out_of_tube/2), the
%   skills that work in it (position_tool, pull) and its geometry are the tube's.
case_apparatus(paddle_tube, tube).

                 /*******************************
                 *     POSE                     *
                 *******************************/

/*  The pose term paddle_pose(Dx, Dy, Roll) (metres, metres, radians):
        Dx   blade centre minus cube centre along the tube axis (+x, away from the robot)
        Dy   lateral offset of the shaft axis from the cube centre (+y)
        Roll rotation about the shaft axis, 0 = blade upright, +-pi/2 = blade flat
*/
spatial_definition(paddle_tube, in_tube(tool, context), paddle_pose(Dx, Dy, _Roll),
                   [Dx =< dx_max, Dx >= dx_min, Dy =< dy_max, Dy >= dy_min]).
spatial_definition(paddle_tube, behind(tool, target), paddle_pose(Dx, _Dy, _Roll),
                   [Dx >= cube_half + blade_half + clearance, Dx =< dx_max]).
spatial_definition(paddle_tube, in_front(tool, target), paddle_pose(Dx, _Dy, _Roll),
                   [Dx =< -(cube_half + blade_half + clearance), Dx >= dx_min]).
spatial_definition(paddle_tube, centred_on(tool, target), paddle_pose(_Dx, Dy, _Roll),
                   [Dy =< 0.005, Dy >= -0.005]).
spatial_definition(paddle_tube, blade_upright(tool), paddle_pose(_Dx, _Dy, Roll),
                   [Roll =< 0.35, Roll >= -0.35]).
spatial_definition(paddle_tube, blade_flat(tool), paddle_pose(_Dx, _Dy, Roll),
                   [Roll >= 1.2]).
spatial_definition(paddle_tube, blade_flat(tool), paddle_pose(_Dx, _Dy, Roll),
                   [Roll =< -1.2]).

%   spatial_meaning(?Case, ?Template, ?Meaning): what a spatial relation means across
%   cases (prolog/transfer.pl: a prior's literal transfers to a case that gives its own
%   relation the same meaning).  working_part_down(tool): the tool's working part (a
%   prong, a blade) turned down across the pull's path, roll within 0.35 rad of it.
spatial_meaning(paddle_tube, blade_upright(tool), working_part_down(tool)).

pose_domain(paddle_tube, paddle_pose(Dx, Dy, Roll),
            [Dx >= -tube_length, Dx =< tube_length, Dy >= -dy_room, Dy =< dy_room,
             Roll >= -pi/2, Roll =< pi/2]).

geometry_default(paddle_tube, cube_half, 0.015, 'half the cube side (3 cm cube)').
geometry_default(paddle_tube, blade_half, 0.006, 'half the blade along the shaft (12 mm blade)').
geometry_default(paddle_tube, clearance, 0.005, 'clearance between blade and cube').
geometry_default(paddle_tube, shaft_half, 0.005, 'half the shaft width (1 cm shaft)').
geometry_default(paddle_tube, tube_length, 0.30, 'tube length (inner)').
geometry_default(paddle_tube, dy_room, 0.10, 'lateral bound of any paddle pose').
geometry_default(paddle_tube, dx_max, 0.07, 'room behind the cube centre to the tube end, minus half the blade').
geometry_default(paddle_tube, dx_min, -0.25, 'mouth to cube centre, negated, plus half the blade').
geometry_default(paddle_tube, dy_max, 0.01, 'largest Dy keeping the shaft in the tube').
geometry_default(paddle_tube, dy_min, -0.01, 'smallest Dy keeping the shaft in the tube').
geometry_default(paddle_tube, reach_loss, -0.04, 'shaft length the held paddle cannot put beyond the mouth (as the hook case measured for a handle)').
geometry_default(paddle_tube, dx_reach, 1.0, 'deepest blade centre the held paddle reaches, minus the cube centre (1 m, no bound, when its shaft is not known)').

%   geometry_value/6, proved on the state: cube_half and tube_length are the tube's;
%   the blade stays inside the tube, the shaft between its walls.
geometry_value(paddle_tube, blade_half, Tool, _Target, _G, V) :-
    nonvar(Tool),
    blade_length_m(Tool, B),
    V is B / 2.
geometry_value(paddle_tube, shaft_half, Tool, _Target, _G, V) :-
    nonvar(Tool),
    shaft_width_m(Tool, W),
    V is W / 2.
geometry_value(paddle_tube, dx_max, _Tool, Target, G, V) :-
    memberchk(blade_half=BH, G),
    tube_dx_max(Target, BH, V).
geometry_value(paddle_tube, dx_min, _Tool, Target, G, V) :-
    memberchk(blade_half=BH, G),
    tube_dx_min(Target, BH, V).
geometry_value(paddle_tube, dy_max, _Tool, Target, G, V) :-
    memberchk(shaft_half=SH, G),
    memberchk(clearance=C, G),
    tube_dy_max(Target, SH, C, V).
geometry_value(paddle_tube, dy_min, _Tool, Target, G, V) :-
    memberchk(shaft_half=SH, G),
    memberchk(clearance=C, G),
    tube_dy_min(Target, SH, C, V).

%   How deep the held paddle reaches: the blade's centre at most the shaft's length,
%   less reach_loss and half the blade, beyond the mouth.
reach_definition(paddle_tube, paddle_pose(Dx, _Dy, _Roll), [Dx =< dx_reach]).

geometry_value(paddle_tube, dx_reach, Tool, Target, G, V) :-
    nonvar(Tool),
    shaft_length_m(Tool, L),
    memberchk(blade_half=BH, G),
    memberchk(reach_loss=Loss, G),
    tube_dx_reach(Tool, Target, L, BH, Loss, V).

%   relative_pose/5, pose_target/5, proved on the state: the blade's centre and the
%   roll against the cube's pose (ontology/world.pl's tip_relative_pose/5,
%   tip_pose_target/5).
relative_pose(paddle_tube, Tool, Target, _G, paddle_pose(Dx, Dy, Roll)) :-
    tip_relative_pose(Tool, Target, Dx, Dy, Roll).

pose_target(paddle_tube, paddle_pose(Dx, Dy, Roll), Target, _G, tip(X, Y, Roll)) :-
    tip_pose_target(Dx, Dy, Target, X, Y).

                 /*******************************
                 *     SIZING A NEW TOOL        *
                 *******************************/

%   The shaft reaches behind a cube at the tube's far end with the gripper outside; the
%   blade turns upright inside the tube.
size_constraint(paddle, tube_length_m(_, L), [shaft_length >= L + reach_margin_m]).
size_constraint(paddle, tube_inner_m(_, W, H),
                [blade_width =< min(W, H) - tube_clearance_m]).

%   The margins reach_margin_m and tube_clearance_m are the tube's
%   (ontology/apparatus/tube.pl, size_parameter/3).
