/*  The rake case: pull a box lying under a low shelf, out of the arm's reach, back
    towards the robot with a hook-like tool.  Everything the engine knows about this
    case is here, in its own module (case_rake: its helpers are its alone); the engine
    asks for it through the hook predicates of ontology/README.md.  Rules marked "proved on the state" take their primitive facts
    (pose/5, shelf_front/4, ...) from the state the engine hands over.

    The apparatus: a shelf (shelf1) whose clear plate stands on four corner legs above
    a base; the space under it is a passage along +x from its front edge, open at the
    back and between the legs.  The box (box1) lies under it; the prong must pass
    under the plate, reach behind the box and drag it out.
*/

case(rake).
case_tool_class(rake, hook_like).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

task_roles(rake, box1, shelf1).
case_goal(rake, [out_from_under(box1, shelf1)]).
case_extra_objects(rake, []).
case_skills(rake, [pick_up, position_tool, pull]).

%   position_tool(T, B, S): move the held tool under the shelf to a pose relative to
%   the box; pull(T, B, S): draw it back out along -x.
innate_skill(rake, position_tool,
             action_model(position_tool, [T-tool, B-target, S-site],
                          [holding(T), under_shelf(B, S)],
                          [spatial_of(T)],
                          [spatial_of(T)])).
innate_skill(rake, pull,
             action_model(pull, [T-tool, _B-target, S-site],
                          [holding(T)],
                          [],
                          [under_shelf(T, S), spatial_of(T)])).

learned_action_names(rake, [name(pull, out_from_under, pull_out)]).
tool_acts_when(rake, held).

%   The rake is always used under the shelf, never tested by placing it elsewhere.
untestable_literals(rake, [under_shelf(_, _)]).

                 /*******************************
                 *     STATE                    *
                 *******************************/

%   The shelf (scene body kind shelf): its front edge's x, the centre line's y and the
%   height midway under the plate; its depth; the room between the legs and under the
%   plate (metres).
primitive_predicate(shelf_front/4).
primitive_predicate(shelf_depth_m/2).
primitive_predicate(shelf_clearance_m/3).

task_predicate(rake, under_shelf/2).
task_predicate(rake, out_from_under/2).

%   under_shelf(?Object, ?Shelf): an uncatalogued object (the box) under the plate.
under_shelf(B, S) :-
    shelf_front(S, FX, FY, FZ),
    shelf_depth_m(S, D),
    shelf_clearance_m(S, W, H),
    pose(B, X, Y, Z, _),
    \+ object_kind(B, _),
    X >= FX,
    X =< FX + D,
    abs(Y - FY) =< W / 2,
    abs(Z - FZ) =< H / 2.

%   out_from_under(?Object, ?Shelf): its centre is in front of the front edge.
out_from_under(B, S) :-
    shelf_front(S, FX, _, _),
    pose(B, X, _, _, _),
    \+ object_kind(B, _),
    X < FX.

%   tool_in_use(?Case, ?Tool), proved on the state: a held tool whose tip is under the
%   plate has spatial literals.
tool_in_use(rake, Tool) :-
    held(Tool),
    shelf_front(S, FX, FY, FZ),
    shelf_depth_m(S, D),
    shelf_clearance_m(S, W, H),
    tip_position(Tool, X, Y, Z),
    X >= FX,
    X =< FX + D,
    abs(Y - FY) =< W / 2,
    abs(Z - FZ) =< H / 2.

                 /*******************************
                 *     POSE                     *
                 *******************************/

/*  rake_pose(Dx, Dy, Roll) (metres, metres, radians): the prong's centre minus the
    box's centre along the shelf's axis (+x) and across it (+y, the handle axis), and
    the tool's roll about its handle (0 = prong down, +-pi/2 = flat).  Behind: the
    prong clears the box (half its extent along x, half the prong, 5 mm); under_shelf:
    the prong between the front and the back edge, the handle between the legs.
*/
spatial_definition(rake, under_shelf(tool, context), rake_pose(Dx, Dy, _),
                   [Dx =< dx_max, Dx >= dx_min, Dy =< dy_max, Dy >= dy_min]).
spatial_definition(rake, behind(tool, target), rake_pose(Dx, _, _),
                   [Dx >= box_half + prong_half + clearance, Dx =< dx_max]).
spatial_definition(rake, in_front(tool, target), rake_pose(Dx, _, _),
                   [Dx =< -(box_half + prong_half + clearance), Dx >= dx_min]).
spatial_definition(rake, centred_on(tool, target), rake_pose(_, Dy, _),
                   [Dy =< 0.005, Dy >= -0.005]).
spatial_definition(rake, hook_down(tool), rake_pose(_, _, Roll),
                   [Roll =< 0.35, Roll >= -0.35]).
spatial_definition(rake, hook_flat(tool), rake_pose(_, _, Roll), [Roll >= 1.2]).
spatial_definition(rake, hook_flat(tool), rake_pose(_, _, Roll), [Roll =< -1.2]).

%   spatial_meaning(?Case, ?Template, ?Meaning): what a spatial relation means across
%   cases (prolog/transfer.pl: a prior's literal transfers to a case that gives its own
%   relation the same meaning).  working_part_down(tool): the tool's working part (a
%   prong, a blade) turned down across the pull's path, roll within 0.35 rad of it.
spatial_meaning(rake, hook_down(tool), working_part_down(tool)).

pose_domain(rake, rake_pose(Dx, Dy, Roll),
            [Dx >= -shelf_depth, Dx =< shelf_depth, Dy >= -dy_room, Dy =< dy_room,
             Roll >= -pi/2, Roll =< pi/2]).

geometry_default(rake, box_half, 0.015, 'half the box extent along x (3 cm)').
geometry_default(rake, prong_half, 0.006, 'half the prong thickness along the handle').
geometry_default(rake, clearance, 0.005, 'clearance between prong and box').
geometry_default(rake, handle_half, 0.005, 'half the handle width').
geometry_default(rake, leg_clearance, 0.01, 'room kept between the handle and a leg').
geometry_default(rake, shelf_depth, 0.30, 'shelf depth').
geometry_default(rake, dy_room, 0.12, 'lateral bound of any rake pose').
geometry_default(rake, dx_max, 0.074, 'back edge minus the box centre, minus half the prong').
geometry_default(rake, dx_min, -0.214, 'front edge minus the box centre, plus half the prong').
geometry_default(rake, dy_max, 0.10, 'largest Dy keeping the handle between the legs').
geometry_default(rake, dy_min, -0.10, 'smallest Dy keeping the handle between the legs').
geometry_default(rake, reach_loss, 0.02, 'handle length the held tool cannot put beyond the front edge: the grip offset less how far the gripper follows it under the plate').
geometry_default(rake, dx_reach, 1.0, 'deepest prong centre the held tool reaches, minus the box centre (1 m, no bound, when its handle is not known)').

%   The box's extent along x from its perceived size and heading.
geometry_value(rake, box_half, _, Target, _, V) :-
    nonvar(Target),
    half_extent_x(Target, V).
geometry_value(rake, prong_half, Tool, _, _, V) :-
    nonvar(Tool),
    prong_half_m(Tool, V).
geometry_value(rake, handle_half, Tool, _, _, V) :-
    nonvar(Tool),
    handle_width_m(Tool, W),
    V is W / 2.
geometry_value(rake, shelf_depth, _, _, _, D) :-
    shelf_depth_m(_, D).
geometry_value(rake, dx_max, _, Target, G, V) :-
    nonvar(Target),
    shelf_front(S, FX, _, _),
    shelf_depth_m(S, D),
    pose(Target, X, _, _, _),
    memberchk(prong_half=PH, G),
    V is FX + D - X - PH.
geometry_value(rake, dx_min, _, Target, G, V) :-
    nonvar(Target),
    shelf_front(_, FX, _, _),
    pose(Target, X, _, _, _),
    memberchk(prong_half=PH, G),
    V is FX - X + PH.
geometry_value(rake, dy_max, _, Target, G, V) :-
    nonvar(Target),
    shelf_front(S, _, FY, _),
    shelf_clearance_m(S, W, _),
    pose(Target, _, Y, _, _),
    memberchk(handle_half=HH, G),
    memberchk(leg_clearance=C, G),
    V is FY - Y + W / 2 - HH - C.
geometry_value(rake, dy_min, _, Target, G, V) :-
    nonvar(Target),
    shelf_front(S, _, FY, _),
    shelf_clearance_m(S, W, _),
    pose(Target, _, Y, _, _),
    memberchk(handle_half=HH, G),
    memberchk(leg_clearance=C, G),
    V is FY - Y - W / 2 + HH + C.

%   How deep the held tool reaches under the shelf (reach_definition/3, read only
%   before a tool is tried in a harder task): the prong's centre at most the handle's
%   length, less reach_loss and half the prong, beyond the front edge.  Measured in
%   the deep shelf, location 1, prong 3.5 cm behind the box: handles of 0.38, 0.42 and
%   0.44 m are all blocked, the gripper stopping at the shelf's front (reach_loss about
%   the grip offset, 0.04 m).  The value, 0.02 m, keeps the reach on the generous side:
%   a pose is called unreachable only where the physics cannot reach it.
reach_definition(rake, rake_pose(Dx, _Dy, _Roll), [Dx =< dx_reach]).

geometry_value(rake, dx_reach, Tool, Target, G, V) :-
    nonvar(Tool),
    nonvar(Target),
    handle_length_m(Tool, L),
    shelf_front(_S, FX, _, _),
    pose(Target, X, _, _, _),
    memberchk(prong_half=PH, G),
    memberchk(reach_loss=Loss, G),
    V is FX + L - Loss - PH - X.

%   The held tool's pose relative to the box (proprioception and camera).
relative_pose(rake, Tool, Target, _, rake_pose(Dx, Dy, Roll)) :-
    tip_relative_pose(Tool, Target, Dx, Dy, Roll).

%   Where a pose puts the prong's centre (x, y) and the roll.
pose_target(rake, rake_pose(Dx, Dy, Roll), Target, _, tip(X, Y, Roll)) :-
    tip_pose_target(Dx, Dy, Target, X, Y).

                 /*******************************
                 *     SIZING A NEW TOOL        *
                 *******************************/

%   The handle reaches behind a box at the shelf's back with the gripper in front of
%   it; the prong, rolled down, passes under the plate beside the handle; a flat prong
%   carried over the box leaves it room.
size_constraint(hook, shelf_depth_m(_, D), [handle_length >= D + reach_margin_m]).
size_constraint(stick, shelf_depth_m(_, D), [handle_length >= D + reach_margin_m]).
size_constraint(hook, shelf_clearance_m(_, _, H),
                [hook_length + handle_width =< H - shelf_prong_margin_m,
                 handle_width =< H - shelf_flat_margin_m]).
size_constraint(stick, shelf_clearance_m(_, _, H),
                [handle_width =< H - shelf_flat_margin_m]).

size_parameter(reach_margin_m, 0.05,
               'handle length beyond the shelf depth: the gripper stays in front of it').
size_parameter(shelf_prong_margin_m, 0.006,
               'room under the plate beside a rolled-down prong and the handle').
size_parameter(shelf_flat_margin_m, 0.026,
               'room under the plate above the handle for a flat prong over the box').
