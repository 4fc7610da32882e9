/*  The lane: a passage along +x (scene body kind lane) from lane_start/4's x for
    lane_length_m/2 metres, lane_room_m/3 wide and high, with a mark at lane_goal/3; an
    uncatalogued object (the task's target, a cube) lies in it, and a held hook-like
    tool, carried over it, drops its prong behind it and pulls it back along -x.
    Written once for every case that uses the lane (ontology/cases/bring_cube.pl, an
    open lane on the table, the goal mark ahead of it; ontology/cases/dislodge_cube.pl,
    the passage of an L-shaped pipe, the mark at its open end), each naming it by a
    fact case_apparatus(Case, lane).

    Plain Prolog data loaded by knowledge:load_ontology/1 into its own module,
    apparatus_lane (apparatus/1 below names it), which sees the shared files only; a
    case that names the lane sees this module after its kind's.  A clause whose first
    argument is a variable answers that hook for every case that uses the lane; the
    helper predicates (lane_*) are called by the cases' own hook clauses, which name
    their pose term.  Each case keeps its goal literal, the learned action's name, its
    pose term, its geometry defaults and its size constraints.  Rules marked "proved on
    the state" take their primitive facts (pose/5, lane_start/4, ...) from the state the
    engine hands over, never from the database.
*/

apparatus(lane).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

%   Objects a plan needs that no literal of the state names.
case_extra_objects(_, []).

%   The innate skills, in the order a plan uses them (pick_up: ontology/skills.pl).
case_skills(_, [pick_up, position_tool, pull]).

%   position_tool(T, B, L): move the held tool over the cube to a pose relative to it;
%   pull(T, B, L): draw it back along -x towards the goal.
innate_skill(_, position_tool,
             action_model(position_tool, [T-tool, B-target, L-site],
                          [holding(T), on_lane(B, L)],
                          [spatial_of(T)],
                          [spatial_of(T)])).
innate_skill(_, pull,
             action_model(pull, [T-tool, _B-target, L-site],
                          [holding(T)],
                          [],
                          [on_lane(T, L), spatial_of(T)])).

%   The tool acts while the robot holds it (its spatial literals count when held).
tool_acts_when(_, held).

%   The tool is always used on the lane, never tested by placing it elsewhere.
untestable_literals(_, [on_lane(_, _)]).

                 /*******************************
                 *     STATE                    *
                 *******************************/

%   The lane: its start's centre (world x, y, z), its length along +x, its width and
%   height, the goal mark's x and y (metres).
primitive_predicate(lane_start/4).
primitive_predicate(lane_length_m/2).
primitive_predicate(lane_room_m/3).
primitive_predicate(lane_goal/3).

%   The goal literal (at_goal/2, dislodged/2) and its task_predicate/2 fact are the
%   case's.
task_predicate(_, on_lane/2).

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

%   tool_in_use(?Case, ?Tool), proved on the state: a held tool whose tip is in the
%   lane's room has spatial literals.
tool_in_use(_, Tool) :-
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

/*  A lane case's pose term is Name(Dx, Dy, Roll) (metres, metres, radians), its name
    the case's (bring_pose, dislodge_pose): the prong's centre minus the cube's centre
    along the lane (+x) and across it (+y, the handle axis), and the tool's roll about
    its handle (0 = prong down, +-pi/2 = flat); the cases' relative_pose/5 and
    pose_target/5 compute them with ontology/world.pl's tip_relative_pose/5 and
    tip_pose_target/5.

    The geometry parameters, in the order the cases list them: box_half, prong_half,
    clearance, lane_length, dy_room, dx_max, dx_min, handle_half, wall_clearance,
    dy_max, dy_min, arm_reach_x, dx_reach.  The cases keep their geometry_default/4
    facts (their values differ); the rules below compute the values from the facts.
    The lane's cases use hook-like tools (ontology/kinds/hook_like.pl): prong_half,
    handle_half and dx_reach read its catalogue.
*/

%   geometry_value(?Case, ?Name, ?Tool, ?Target, +Geometry, -Value), proved on the
%   state: the parameter's value from the facts.  Tool and Target may be unbound (then
%   only facts naming neither are used).  box_half: the cube's extent along x from its
%   perceived size and heading.
geometry_value(_, box_half, _, Target, _, V) :-
    nonvar(Target),
    half_extent_x(Target, V).
geometry_value(_, prong_half, Tool, _, _, V) :-
    nonvar(Tool),
    (   hook_width_m(Tool, W)
    ->  true
    ;   handle_width_m(Tool, W)
    ),
    V is W / 2.
geometry_value(_, lane_length, _, _, _, D) :-
    lane_length_m(_, D).
%   The prong stays on the lane, from its start to its end, relative to the cube.
geometry_value(_, dx_max, _, Target, G, V) :-
    nonvar(Target),
    lane_start(L, SX, _, _),
    lane_length_m(L, D),
    pose(Target, X, _, _, _),
    memberchk(prong_half=PH, G),
    V is SX + D - X - PH.
geometry_value(_, dx_min, _, Target, G, V) :-
    nonvar(Target),
    lane_start(_, SX, _, _),
    pose(Target, X, _, _, _),
    memberchk(prong_half=PH, G),
    V is SX - X + PH.

%   The handle stays inside the lane's width, wall_clearance from its sides.
geometry_value(_, handle_half, Tool, _, _, V) :-
    nonvar(Tool),
    handle_width_m(Tool, W),
    V is W / 2.
geometry_value(_, dy_max, _, Target, G, V) :-
    nonvar(Target),
    lane_start(L, _, LY, _),
    lane_room_m(L, W, _),
    pose(Target, _, Y, _, _),
    memberchk(handle_half=HH, G),
    memberchk(wall_clearance=C, G),
    V is LY - Y + W / 2 - HH - C.
geometry_value(_, dy_min, _, Target, G, V) :-
    nonvar(Target),
    lane_start(L, _, LY, _),
    lane_room_m(L, W, _),
    pose(Target, _, Y, _, _),
    memberchk(handle_half=HH, G),
    memberchk(wall_clearance=C, G),
    V is LY - Y - W / 2 + HH + C.

%   How far the held tool reaches (the cases' reach_definition/3, read only before a
%   tool is tried in a harder task): the prong's centre at most the handle's length
%   beyond arm_reach_x.
geometry_value(_, dx_reach, Tool, Target, G, V) :-
    nonvar(Tool),
    nonvar(Target),
    handle_length_m(Tool, Len),
    pose(Target, X, _, _, _),
    memberchk(arm_reach_x=R, G),
    V is R + Len - X.
