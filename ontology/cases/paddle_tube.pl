/*  The paddle case: pull a cube out of a closed tube with a paddle, its blade upright
    behind the cube.  The hook case's apparatus (worlds/paddle_tube is the hook world
    with paddles), a tool kind no paper case has (ontology/kinds/paddle.pl).  The
    engine asks for everything here through the hook predicates of ontology/README.md.

    Plain Prolog data loaded into this case's own module (case_paddle_tube) by
    knowledge:load_ontology/1.  Rules marked "proved on the state" take their primitive
    facts from the state the engine hands over.  The tube is the hook case's and is
    perceived the same way (the tube's primitive facts, ontology/cases/hook.pl); its task
    literals and margins are written again below, since a case sees no other case's
    rules.
*/

case(paddle_tube).

case_tool_class(paddle_tube, paddle).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

task_roles(paddle_tube, cube1, tube1).

case_goal(paddle_tube, [out_of_tube(cube1, tube1)]).

case_extra_objects(paddle_tube, []).

case_skills(paddle_tube, [pick_up, position_tool, pull]).

%   position_tool(T, C, Tube): move the held paddle to a pose relative to the cube.
innate_skill(paddle_tube, position_tool,
             action_model(position_tool, [T-tool, C-target, Tube-site],
                          [holding(T), in_tube(C, Tube)],
                          [spatial_of(T)],
                          [spatial_of(T)])).
%   pull(T, C, Tube): draw the held paddle back out of the tube along its axis.
innate_skill(paddle_tube, pull,
             action_model(pull, [T-tool, _C-target, Tube-site],
                          [holding(T)],
                          [],
                          [in_tube(T, Tube), spatial_of(T)])).

learned_action_names(paddle_tube, [name(pull, out_of_tube, pull_out)]).

tool_acts_when(paddle_tube, held).

untestable_literals(paddle_tube, [in_tube(_, _)]).

task_predicate(paddle_tube, in_tube/2).
task_predicate(paddle_tube, out_of_tube/2).

%   in_tube(?Object, ?Tube): an uncatalogued object (the cube) whose centre lies inside
%   the tube's inner box; out_of_tube/2 its complement.
in_tube(C, Tube) :-
    tube_mouth(Tube, MX, MY, MZ),
    tube_length_m(Tube, L),
    tube_inner_m(Tube, W, H),
    pose(C, X, Y, Z, _Yaw),
    \+ object_kind(C, _),
    inside_tube_box_(X, Y, Z, MX, MY, MZ, L, W, H).

out_of_tube(C, Tube) :-
    tube_mouth(Tube, _, _, _),
    pose(C, _, _, _, _),
    \+ object_kind(C, _),
    \+ in_tube(C, Tube).

%   tool_in_use(?Case, ?Tool), proved on the state: a held paddle whose blade's centre
%   (its tip position) lies inside the tube's inner box.
tool_in_use(paddle_tube, Tool) :-
    held(Tool),
    tube_mouth(Tube, MX, MY, MZ),
    tube_length_m(Tube, L),
    tube_inner_m(Tube, W, H),
    tip_position(Tool, X, Y, Z),
    inside_tube_box_(X, Y, Z, MX, MY, MZ, L, W, H).

inside_tube_box_(X, Y, Z, MX, MY, MZ, L, W, H) :-
    X >= MX,
    X =< MX + L,
    abs(Y - MY) =< W / 2,
    abs(Z - MZ) =< H / 2.

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

geometry_value(paddle_tube, cube_half, _Tool, Target, _G, V) :-
    nonvar(Target),
    size(Target, Sx, _, _),
    V is Sx / 2.
geometry_value(paddle_tube, blade_half, Tool, _Target, _G, V) :-
    nonvar(Tool),
    blade_length_m(Tool, B),
    V is B / 2.
geometry_value(paddle_tube, shaft_half, Tool, _Target, _G, V) :-
    nonvar(Tool),
    shaft_width_m(Tool, W),
    V is W / 2.
geometry_value(paddle_tube, tube_length, _Tool, _Target, _G, L) :-
    tube_length_m(_, L).
geometry_value(paddle_tube, dx_max, _Tool, Target, G, DxMax) :-
    nonvar(Target),
    tube_mouth(Tube, MX, _, _),
    tube_length_m(Tube, L),
    pose(Target, CX, _, _, _),
    memberchk(blade_half=BH, G),
    DxMax is MX + L - CX - BH.
geometry_value(paddle_tube, dx_min, _Tool, Target, G, DxMin) :-
    nonvar(Target),
    tube_mouth(Tube, MX, _, _),
    tube_length_m(Tube, _),
    pose(Target, CX, _, _, _),
    memberchk(blade_half=BH, G),
    DxMin is MX - CX + BH.
geometry_value(paddle_tube, dy_max, _Tool, Target, G, DyMax) :-
    nonvar(Target),
    tube_mouth(Tube, _, MY, _),
    tube_length_m(Tube, _),
    tube_inner_m(Tube, W, _),
    pose(Target, _, CY, _, _),
    memberchk(shaft_half=SH, G),
    memberchk(clearance=C, G),
    Room is W / 2 - SH - C,
    DyMax is MY - CY + Room.
geometry_value(paddle_tube, dy_min, _Tool, Target, G, DyMin) :-
    nonvar(Target),
    tube_mouth(Tube, _, MY, _),
    tube_length_m(Tube, _),
    tube_inner_m(Tube, W, _),
    pose(Target, _, CY, _, _),
    memberchk(shaft_half=SH, G),
    memberchk(clearance=C, G),
    Room is W / 2 - SH - C,
    DyMin is MY - CY - Room.

%   How deep the held paddle reaches: the blade's centre at most the shaft's length,
%   less reach_loss and half the blade, beyond the mouth.
reach_definition(paddle_tube, paddle_pose(Dx, _Dy, _Roll), [Dx =< dx_reach]).

geometry_value(paddle_tube, dx_reach, Tool, Target, G, V) :-
    nonvar(Tool),
    nonvar(Target),
    shaft_length_m(Tool, L),
    tube_mouth(_Tube, MX, _, _),
    pose(Target, CX, _, _, _),
    memberchk(blade_half=BH, G),
    memberchk(reach_loss=Loss, G),
    V is MX + L - Loss - BH - CX.

%   relative_pose/5, proved on the state: the blade's centre and the roll
%   (proprioception) against the cube's pose (camera).
relative_pose(paddle_tube, Tool, Target, _G, paddle_pose(Dx, Dy, Roll)) :-
    tip_position(Tool, TX, TY, _),
    tool_roll(Tool, Roll),
    pose(Target, CX, CY, _, _),
    Dx is TX - CX,
    Dy is TY - CY.

%   pose_target/5, proved on the state: the blade centre's world X and Y and the roll.
pose_target(paddle_tube, paddle_pose(Dx, Dy, Roll), Target, _G, tip(X, Y, Roll)) :-
    pose(Target, CX, CY, _, _),
    X is CX + Dx,
    Y is CY + Dy.

                 /*******************************
                 *     SIZING A NEW TOOL        *
                 *******************************/

%   The shaft reaches behind a cube at the tube's far end with the gripper outside; the
%   blade turns upright inside the tube.
size_constraint(paddle, tube_length_m(_, L), [shaft_length >= L + reach_margin_m]).
size_constraint(paddle, tube_inner_m(_, W, H),
                [blade_width =< min(W, H) - tube_clearance_m]).

%   size_parameter(?Name, ?Value, ?Meaning): margins used by the size constraints
%   (metres); a context fact Name(Value) overrides the value.
size_parameter(reach_margin_m, 0.05,
               'shaft length beyond the tube length: the grip and the gripper stay outside the mouth').
size_parameter(tube_clearance_m, 0.005,
               'free space left between the blade and the tube walls').
