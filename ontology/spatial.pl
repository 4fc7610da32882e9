/*  Spatial literals: their definitions over the pose numbers, written once.

    Plain Prolog data loaded into the knowledge base by knowledge:load_ontology/1.
    abstract_state:abstract_state/3 evaluates them on measured numbers (literal true or
    false); geometry_clp:pose_constraints/5 posts them as CLP(R) constraints (literal
    required, or its complement required).

    spatial_definition(?Case, ?Literal, ?PoseTerm, ?Constraints)
        Literal holds when every constraint of Constraints (a list, read as a
        conjunction) holds for the numbers of PoseTerm; several clauses for one literal
        are alternatives (a disjunction).  Literal's arguments are the roles `tool`,
        `target` and `context`, replaced by object names when the literal is used
        (behind(tool, target) stands for behind(hook_a2, cube1)).  Constraints are
        linear comparisons (>=, =<, >, <) whose right-hand sides may name geometry
        parameters (geometry_default/4 below), filled from the task's facts.
        The complement of a clause tries its comparisons in the order written: list
        first the one whose violation is the meaningful "other side".

    Case hook, PoseTerm hook_pose(Dx, Dy, Roll) (metres, metres, radians):
        Dx   prong centre minus cube centre along the tube axis (+x, away from the robot)
        Dy   lateral offset of the handle axis from the cube centre (+y)
        Roll rotation about the handle axis, 0 = prong down, +-pi/2 = prong flat
    Case wedge, PoseTerm wedge_pose(R, Gap, Yaw) (metres, metres, radians):
        R    hinge axis to wedge centre
        Gap  open door face to wedge tip, along the door's closing sweep
        Yaw  wedge heading minus the door's direction of motion, 0 = tip at the door
*/

% Hook case.  The prong must clear the cube (half its size plus half the prong's
% thickness plus 5 mm) and stay inside the tube (dx_min .. dx_max).
spatial_definition(hook, in_tube(tool, context), hook_pose(Dx, Dy, _Roll),
                   [Dx =< dx_max, Dx >= dx_min, Dy =< dy_max, Dy >= dy_min]).
spatial_definition(hook, behind(tool, target), hook_pose(Dx, _Dy, _Roll),
                   [Dx >= cube_half + prong_half + clearance, Dx =< dx_max]).
spatial_definition(hook, in_front(tool, target), hook_pose(Dx, _Dy, _Roll),
                   [Dx =< -(cube_half + prong_half + clearance), Dx >= dx_min]).
spatial_definition(hook, centred_on(tool, target), hook_pose(_Dx, Dy, _Roll),
                   [Dy =< 0.005, Dy >= -0.005]).
spatial_definition(hook, hook_down(tool), hook_pose(_Dx, _Dy, Roll),
                   [Roll =< 0.35, Roll >= -0.35]).
spatial_definition(hook, hook_flat(tool), hook_pose(_Dx, _Dy, Roll),
                   [Roll >= 1.2]).
spatial_definition(hook, hook_flat(tool), hook_pose(_Dx, _Dy, Roll),
                   [Roll =< -1.2]).

% Wedge case (door 0.8 m wide).
spatial_definition(wedge, near(tool, target), wedge_pose(_R, Gap, _Yaw),
                   [Gap =< 0.10]).
spatial_definition(wedge, far(tool, target), wedge_pose(_R, Gap, _Yaw),
                   [Gap >= 0.30]).
spatial_definition(wedge, far_from_hinge(tool, target), wedge_pose(R, _Gap, _Yaw),
                   [R >= 0.45]).
spatial_definition(wedge, near_hinge(tool, target), wedge_pose(R, _Gap, _Yaw),
                   [R =< 0.30]).
spatial_definition(wedge, tip_towards(tool, target), wedge_pose(_R, _Gap, Yaw),
                   [Yaw =< 0.3, Yaw >= -0.3]).
spatial_definition(wedge, tip_away(tool, target), wedge_pose(_R, _Gap, Yaw),
                   [Yaw >= pi - 0.3]).
spatial_definition(wedge, tip_away(tool, target), wedge_pose(_R, _Gap, Yaw),
                   [Yaw =< -pi + 0.3]).

%   pose_domain(?Case, ?PoseTerm, ?Constraints): where a pose can be at all.  Posted by
%   the CLP(R) models under every query (never named in a conflict); keeps every pose
%   variable bounded so that a midpoint exists.
%   The hook's roll stays within +-pi/2 (prong down to prong flat on either side): a
%   prong rolled further points up, away from anything it could pull, and the arm's
%   insertion motion is planned for that range.
pose_domain(hook, hook_pose(Dx, Dy, Roll),
            [Dx >= -tube_length, Dx =< tube_length, Dy >= -dy_room, Dy =< dy_room,
             Roll >= -pi/2, Roll =< pi/2]).
%   The wedge lies under the door's sweep, ahead of the open door (Gap >= 0), and not
%   beyond the closed door's line: Gap =< A * R - wedge_half - door_half_thickness.
pose_domain(wedge, wedge_pose(R, Gap, Yaw),
            [R >= r_min, R =< door_width, Gap >= 0,
             Gap =< door_angle * R - wedge_half - door_half_thickness,
             Yaw > -pi, Yaw =< pi]).

%   geometry_default(?Case, ?Name, ?Value, ?Meaning): the geometry parameters, with the
%   values used when the task's facts do not give them (metres, radians).
%   geometry_clp:pose_geometry/5 derives them from facts where it can (its PlDoc says
%   from which).
geometry_default(hook, cube_half, 0.015, 'half the cube side (3 cm cube)').
geometry_default(hook, prong_half, 0.005, 'half the prong thickness along the handle (1 cm prong)').
geometry_default(hook, clearance, 0.005, 'clearance between prong and cube').
geometry_default(hook, dx_max, 0.07, 'room behind the cube centre to the tube end, minus half the prong').
geometry_default(hook, dx_min, -0.25, 'mouth to cube centre, negated, plus half the prong').
geometry_default(hook, dy_max, 0.01, 'largest Dy keeping the handle in the tube: tube axis minus cube centre, plus inner half width minus handle half width minus clearance').
geometry_default(hook, dy_min, -0.01, 'smallest Dy keeping the handle in the tube').
geometry_default(hook, handle_half, 0.005, 'half the handle width (1 cm handle)').
geometry_default(hook, tube_length, 0.30, 'tube length (inner)').
geometry_default(hook, dy_room, 0.10, 'lateral bound of any hook pose').
geometry_default(wedge, r_min, 0.05, 'closest wedge centre to the hinge axis').
geometry_default(wedge, door_width, 0.80, 'door width: the hinge to the free edge').
geometry_default(wedge, door_angle, 1.0, 'door opening when the trial starts (radians)').
geometry_default(wedge, wedge_half, 0.05, 'wedge centre to tip (half the block length)').
geometry_default(wedge, door_half_thickness, 0.02, 'half the door panel thickness').
