/*  The tube: a closed tube whose axis runs along +x from its mouth, a cube (the task's
    target) lying inside it, and the task of pulling the cube out with a held tool
    whose tip reaches behind it.  Written once for every case that uses the tube
    (ontology/cases/hook.pl with hook-like tools, ontology/cases/paddle_tube.pl with
    paddles), each naming it by a fact case_apparatus(Case, tube).

    Plain Prolog data loaded by knowledge:load_ontology/1 into its own module,
    apparatus_tube (apparatus/1 below names it), which sees the shared files only; a
    case that names the tube sees this module after its kind's.  A clause whose first
    argument is a variable answers that hook for every case that uses the tube; the
    helper predicates (tube_*) are called by the cases' own hook clauses, which name
    their pose term, their tool's parts and their catalogue facts.  Rules marked
    "proved on the state" take their primitive facts (pose/5, tube_mouth/4, ...) from
    the state the engine hands over, never from the database.
*/

apparatus(tube).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

%   Objects a plan needs that no literal of the state names.
case_extra_objects(_, []).

%   The innate skills, in the order a plan uses them (pick_up: ontology/skills.pl).
case_skills(_, [pick_up, position_tool, pull]).

%   position_tool(T, C, Tube): move the held tool to a pose relative to the cube inside
%   the tube; which spatial literals become true is the pose's business (spatial_of/1).
innate_skill(_, position_tool,
             action_model(position_tool, [T-tool, C-target, Tube-site],
                          [holding(T), in_tube(C, Tube)],
                          [spatial_of(T)],
                          [spatial_of(T)])).
%   pull(T, C, Tube): draw the held tool back out of the tube along its axis.
innate_skill(_, pull,
             action_model(pull, [T-tool, _C-target, Tube-site],
                          [holding(T)],
                          [],
                          [in_tube(T, Tube), spatial_of(T)])).

%   The name of the action learned from the demonstration: the pull whose unexplained
%   effect is out_of_tube/2 is pull_out.
learned_action_names(_, [name(pull, out_of_tube, pull_out)]).

%   The tool acts while the robot holds it (its spatial literals count when held).
tool_acts_when(_, held).

%   Spatial literals that are preconditions of the motion rather than pose choices:
%   the tool is always used inside the tube, never tested by placing it outside.
untestable_literals(_, [in_tube(_, _)]).

                 /*******************************
                 *     STATE                    *
                 *******************************/

%   The tube: mouth centre (world x, y, z), inner length along +x, inner width and
%   height (metres).
primitive_predicate(tube_mouth/4).
primitive_predicate(tube_length_m/2).
primitive_predicate(tube_inner_m/3).

task_predicate(_, in_tube/2).
task_predicate(_, out_of_tube/2).

%   in_tube(?Object, ?Tube): an uncatalogued object (the cube) whose centre lies inside
%   the tube's inner box.
in_tube(C, Tube) :-
    tube_mouth(Tube, MX, MY, MZ),
    tube_length_m(Tube, L),
    tube_inner_m(Tube, W, H),
    pose(C, X, Y, Z, _Yaw),
    \+ object_kind(C, _),
    X >= MX,
    X =< MX + L,
    abs(Y - MY) =< W / 2,
    abs(Z - MZ) =< H / 2.

out_of_tube(C, Tube) :-
    tube_mouth(Tube, _, _, _),
    pose(C, _, _, _, _),
    \+ object_kind(C, _),
    \+ in_tube(C, Tube).

%   tool_in_use(?Case, ?Tool), proved on the state: a held tool whose tip (a hook's
%   prong, a paddle's blade centre) lies inside the tube's inner box has spatial
%   literals.
tool_in_use(_, Tool) :-
    held(Tool),
    tip_in_tube(Tool).

tip_in_tube(Tool) :-
    tube_mouth(Tube, MX, MY, MZ),
    tube_length_m(Tube, L),
    tube_inner_m(Tube, W, H),
    tip_position(Tool, X, Y, Z),
    X >= MX,
    X =< MX + L,
    abs(Y - MY) =< W / 2,
    abs(Z - MZ) =< H / 2.

                 /*******************************
                 *     POSE                     *
                 *******************************/

/*  A tube case's pose term is Name(Dx, Dy, Roll) (metres, metres, radians), its name
    the case's (hook_pose, paddle_pose):
        Dx   the tool's tip (the part that reaches behind the cube) minus the cube's
             centre along the tube axis (+x, away from the robot)
        Dy   lateral offset of the handle (shaft) axis from the cube centre (+y)
        Roll rotation about the handle axis, 0 = the tip's part down or upright

    The geometry parameters of the tube, in the order the cases list them after their
    tool's own (cube_half, the tip's half thickness along the handle, clearance, the
    handle's half width): tube_length, dy_room, dx_max, dx_min, dy_max, dy_min,
    reach_loss, dx_reach.  The cases keep their geometry_default/4 facts (their
    meanings name the tool's parts); the rules below compute the values.
*/

%   geometry_value(?Case, ?Name, ?Tool, ?Target, +Geometry, -Value), proved on the
%   state: the parameter's value from the facts, for the parameters that name no part
%   of the tool.  Tool and Target may be unbound (then only facts naming neither are
%   used).
geometry_value(_, cube_half, _Tool, Target, _G, V) :-
    nonvar(Target),
    size(Target, Sx, _, _),
    V is Sx / 2.
geometry_value(_, tube_length, _Tool, _Target, _G, L) :-
    tube_length_m(_, L).

%   tube_dx_max(+Target, +TipHalf, -DxMax), tube_dx_min(+Target, +TipHalf, -DxMin),
%   proved on the state: the tip stays inside the tube, from the mouth to the far end,
%   relative to the cube; TipHalf is half the tip's thickness along the handle.
tube_dx_max(Target, TipHalf, DxMax) :-
    nonvar(Target),
    tube_mouth(Tube, MX, _, _),
    tube_length_m(Tube, L),
    pose(Target, CX, _, _, _),
    DxMax is MX + L - CX - TipHalf.
tube_dx_min(Target, TipHalf, DxMin) :-
    nonvar(Target),
    tube_mouth(Tube, MX, _, _),
    tube_length_m(Tube, _),
    pose(Target, CX, _, _, _),
    DxMin is MX - CX + TipHalf.

%   tube_dy_max(+Target, +HandleHalf, +Clearance, -DyMax), tube_dy_min/4, proved on
%   the state: the largest (smallest) Dy keeping the handle in the tube: tube axis
%   minus cube centre, plus (minus) the inner half width less the handle's half width
%   and the clearance.
tube_dy_max(Target, HandleHalf, C, DyMax) :-
    nonvar(Target),
    tube_mouth(Tube, _, MY, _),
    tube_length_m(Tube, _),
    tube_inner_m(Tube, W, _),
    pose(Target, _, CY, _, _),
    Room is W / 2 - HandleHalf - C,
    DyMax is MY - CY + Room.
tube_dy_min(Target, HandleHalf, C, DyMin) :-
    nonvar(Target),
    tube_mouth(Tube, _, MY, _),
    tube_length_m(Tube, _),
    tube_inner_m(Tube, W, _),
    pose(Target, _, CY, _, _),
    Room is W / 2 - HandleHalf - C,
    DyMin is MY - CY - Room.

%   tube_dx_reach(+Tool, +Target, +HandleLength, +TipHalf, +Loss, -Reach), proved on
%   the state: the deepest tip centre the held tool reaches, minus the cube centre:
%   the handle's length, less reach_loss (the part of the handle the gripper keeps
%   outside the mouth) and half the tip, beyond the mouth.
tube_dx_reach(Tool, Target, HandleLength, TipHalf, Loss, V) :-
    nonvar(Tool),
    nonvar(Target),
    tube_mouth(_Tube, MX, _, _),
    pose(Target, CX, _, _, _),
    V is MX + HandleLength - Loss - TipHalf - CX.

                 /*******************************
                 *     SIZING A NEW TOOL        *
                 *******************************/

%   size_parameter(?Name, ?Value, ?Meaning): margins used by the size constraints the
%   tube's cases put on their new tools (metres); a context fact Name(Value) overrides
%   the value.
size_parameter(reach_margin_m, 0.05,
               'tool length beyond the tube length: the grip and the gripper stay outside the mouth').
size_parameter(tube_clearance_m, 0.005,
               'free space left between the tool cross-section and the tube walls').
