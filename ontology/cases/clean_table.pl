/*  The clean_table case: RoboToolBench's CleanTable (VLMgineer, arXiv 2507.12644;
    worlds/clean_table/).  The Panda holds a pusher, lowers its walled head behind a
    field of cubes scattered on the table and sweeps them along +x into a goal circle
    (the verdict is the benchmark's reward, measured by the physics).

    Plain Prolog data loaded into this case's own module (case/1 names it), which sees
    the pusher kind's module, the goal zone's (ontology/apparatus/goal_zone.pl: the
    goal disc, in_zone/2, out_of_zone/2, the positioning skill) and the shared files.
    The cubes are one target, their field: the scatter reports where they lie as
    pose/5 (the field's middle) and size/4 (its extent).
*/

case(clean_table).

case_apparatus(clean_table, goal_zone).

case_tool_class(clean_table, pusher).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

task_roles(clean_table, cubes, goal1).

case_goal(clean_table, [in_zone(cubes, goal1)]).

case_skills(clean_table, [pick_up, position_tool, sweep]).

%   sweep(T, C, Zone): sweep the held pusher along +x to the goal and let the cubes rest.
innate_skill(clean_table, sweep,
             action_model(sweep, [T-tool, _C-target, _Zone-site],
                          [holding(T)],
                          [],
                          [spatial_of(T)])).

learned_action_names(clean_table, [name(sweep, in_zone, sweep_in)]).

                 /*******************************
                 *     POSE                     *
                 *******************************/

/*  The pose term sweep_pose(Dx, Dy) (metres): the middle of the room the head's walls
    enclose minus the field's near edge (x) and its middle (y).  The sweep runs along +x.
*/
%   behind: the head's wings clear of the nearest cubes, within a band behind them.
spatial_definition(clean_table, behind(tool, target), sweep_pose(Dx, _Dy),
                   [Dx =< -(wing_half + clearance), Dx >= -(wing_half + clearance + band)]).
%   over: the head's middle past the near edge (it comes down on cubes).
spatial_definition(clean_table, over(tool, target), sweep_pose(Dx, _Dy),
                   [Dx >= clearance, Dx =< dx_room]).
%   centred_on: the head's middle within 2 cm of the field's middle across.
spatial_definition(clean_table, centred_on(tool, target), sweep_pose(_Dx, Dy),
                   [Dy >= -align, Dy =< align]).
%   aside: the head's middle off the field's middle across by more than 5 cm.
spatial_definition(clean_table, aside(tool, target), sweep_pose(_Dx, Dy),
                   [Dy >= 0.05, Dy =< dy_room]).

pose_domain(clean_table, sweep_pose(Dx, Dy),
            [Dx >= -dx_room, Dx =< dx_room, Dy >= -dy_room, Dy =< dy_room]).

geometry_default(clean_table, wing_half, 0.025, 'half the wings'' length along x').
geometry_default(clean_table, clearance, 0.01, 'clearance between the wings and the nearest cube').
geometry_default(clean_table, band, 0.04, 'width of the band behind the cubes the head comes down in, m').
geometry_default(clean_table, align, 0.02, 'how far the head''s middle may lie off the field''s middle across, m').
geometry_default(clean_table, dx_room, 0.2, 'bound of Dx either side of the near edge').
geometry_default(clean_table, dy_room, 0.2, 'bound of Dy either side of the field''s middle').

geometry_value(clean_table, wing_half, Tool, _Target, _G, V) :-
    nonvar(Tool),
    wing_length_m(Tool, L),
    V is L / 2.

%   No reach relation: whether the arm sweeps the head far enough is the physics'.
reach_definition(clean_table, sweep_pose(_, _), []).

relative_pose(clean_table, Tool, Target, _G, sweep_pose(Dx, Dy)) :-
    tip_position(Tool, TX, TY, _),
    pose(Target, CX, CY, _, _),
    size(Target, SX, _, _),
    Dx is TX - (CX - SX / 2),
    Dy is TY - CY.

%   pose_target: tip(X, Y, Roll), the head's middle over the table, head down.
pose_target(clean_table, sweep_pose(Dx, Dy), Target, _G, tip(X, Y, 0.0)) :-
    pose(Target, CX, CY, _, _),
    size(Target, SX, _, _),
    X is CX - SX / 2 + Dx,
    Y is CY + Dy.

                 /*******************************
                 *     SIZING A NEW TOOL        *
                 *******************************/

%   A new pusher's mouth (the plate and both wings' spread) is wider than the field of
%   cubes; its plate no wider than the goal takes across (within 0.16 m, L1, of the
%   centre), so that what it gathers ends in the goal, and no narrower than two rows of
%   the cubes take (measured); each wing spreads at most twice
%   its length (steeper, a cube meets it nearly square on and stops instead of sliding
%   in).  The sweep bounds the pole and the wings: the arm follows it in a straight line
%   with the hand 0.2-0.9 m in front of the base, the plate must run from 1 cm plus the
%   wings behind the nearest cube (x = 0.485) to x = 1.07 (trials on the Panda).
size_constraint(pusher, size(_, _, W, _),
                [plate_width + 2 * wing_spread >= W + mouth_margin_m,
                 plate_width =< max_plate_m, plate_width >= min_plate_m,
                 wing_spread =< 2 * wing_length]).
size_constraint(pusher, reach_zone(_, _, _, _),
                [pole_length >= min_pole_m, pole_length =< max_pole_m,
                 wing_length >= min_wing_m, wing_length =< max_wing_m]).

size_parameter(mouth_margin_m, 0.04, 'the mouth wider than the field of cubes, m').
size_parameter(max_plate_m, 0.24, 'the plate no wider than the goal takes across, m').
size_parameter(min_plate_m, 0.22, 'a plate wide enough to hold the eight cubes in two rows (0.20 m: one cube of eight left out), m').
size_parameter(min_pole_m, 0.22, 'a pole long enough for the plate to reach x = 1.07, m').
size_parameter(max_pole_m, 0.24, 'a pole short enough for the plate to start behind the cubes (and a head that splits into pieces the printer takes), m').
size_parameter(min_wing_m, 0.06, 'wings long enough to gather the cubes, m').
size_parameter(max_wing_m, 0.08, 'wings short enough for the head to start behind the cubes, m').
