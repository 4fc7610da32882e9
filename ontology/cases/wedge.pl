/*  The wedge case (paper, case 2): hold a self-closing door open with a block placed on
    the floor under its sweep.  Everything the engine knows about this case is here;
    the engine asks for it through the hook predicates of ontology/README.md.

    Plain Prolog data loaded by knowledge:load_ontology/1 into this case's own module
    (case/1 below names it), which sees its tool kind's module and the shared files:
    a helper predicate here is this case's alone.  Rules marked "proved on the state"
    are proved by case:case_prove/2: their
    primitive facts come from the state the engine hands over.

    The apparatus: a door (door1) hinged at a vertical axis, closing counter-clockwise
    by itself once released; the wedge lies on the floor (floor1) in its sweep.
*/

case(wedge).

%   The case's tools are blocks (ontology/kinds/block.pl).
case_tool_class(wedge, block).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

task_roles(wedge, door1, floor1).

case_goal(wedge, [door_held(door1)]).

%   The floor appears in no literal of the state, but place/3 needs it.
case_extra_objects(wedge, [floor1-site]).

case_skills(wedge, [pick_up, place, release_door]).

%   place(W, D, Floor): put the held block down on the floor at a pose relative to the
%   door and let go of it.
innate_skill(wedge, place,
             action_model(place, [W-tool, D-target, _Floor-site],
                          [holding(W), door_open(D)],
                          [gripper_empty, spatial_of(W)],
                          [holding(W), spatial_of(W)])).
%   release_door(D): let go of the open door; its closing is the world's response.
innate_skill(wedge, release_door,
             action_model(release_door, [D-target],
                          [door_open(D)],
                          [],
                          [])).

learned_action_names(wedge, [name(release_door, door_held, hold_door)]).

%   The block acts once placed: the spatial literals speak of a block resting on the
%   floor, not of one still in the gripper.
tool_acts_when(wedge, placed).

untestable_literals(wedge, []).

                 /*******************************
                 *     STATE                    *
                 *******************************/

%   The door: hinge axis (world x, y), width (hinge to free edge), the heading of the
%   closed door, its opening angle (radians, counter-clockwise from closed), and
%   whether it stayed open after release.
primitive_predicate(hinge/3).
primitive_predicate(door_width_m/2).
primitive_predicate(door_closed_heading/2).
primitive_predicate(door_angle/2).
primitive_predicate(door_held/1).

task_predicate(wedge, door_open/1).
task_predicate(wedge, door_held/1).

%   door_open(?Door): the door stands open by more than 0.05 rad (about 3 degrees).
door_open(D) :-
    door_angle(D, A),
    A > 0.05.

%   tool_in_use(?Case, ?Tool), proved on the state: every held block, and every block
%   lying in the door's sweep (0 =< Phi =< A, R =< door width).
tool_in_use(wedge, Tool) :-
    held(Tool).
tool_in_use(wedge, Tool) :-
    object_kind(Tool, block),
    \+ held(Tool),
    block_in_sweep(Tool).

block_in_sweep(W) :-
    task_roles(wedge, Door, _),
    door_polar(W, Door, R, Phi, A),
    door_width_m(Door, Width),
    R =< Width,
    Phi >= 0,
    Phi =< A.

%   door_polar(+W, +Door, -R, -Phi, -A): W's centre in polar coordinates about the
%   hinge, Phi relative to the closed door's heading, wrapped to (-pi, pi]; A the
%   door's opening.
door_polar(W, Door, R, Phi, A) :-
    hinge(Door, HX, HY),
    door_closed_heading(Door, Theta0),
    door_angle(Door, A),
    pose(W, X, Y, _, _),
    R is sqrt((X - HX)**2 + (Y - HY)**2),
    wrap_angle(atan2(Y - HY, X - HX) - Theta0, Phi).

                 /*******************************
                 *     POSE                     *
                 *******************************/

/*  The pose term wedge_pose(R, Gap, Yaw) (metres, metres, radians):
        R    hinge axis to wedge centre
        Gap  open door face to wedge tip, along the door's closing sweep
        Yaw  wedge heading minus the door's direction of motion, 0 = tip at the door
    Door 0.8 m wide.
*/
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

%   The wedge lies under the door's sweep, ahead of the open door (Gap >= 0), and not
%   beyond the closed door's line: Gap =< A * R - wedge_half - door_half_thickness.
pose_domain(wedge, wedge_pose(R, Gap, Yaw),
            [R >= r_min, R =< door_width, Gap >= 0,
             Gap =< door_angle * R - wedge_half - door_half_thickness,
             Yaw > -pi, Yaw =< pi]).

%   reach_definition/3: the arm puts the block anywhere under the door's sweep, so no
%   pose is out of reach; whether a block holds the door is a matter of force (its
%   slope against the closer), which the pose model cannot tell.
reach_definition(wedge, wedge_pose(_R, _Gap, _Yaw), []).

geometry_default(wedge, r_min, 0.05, 'closest wedge centre to the hinge axis').
geometry_default(wedge, door_width, 0.80, 'door width: the hinge to the free edge').
geometry_default(wedge, door_angle, 1.0, 'door opening when the trial starts (radians)').
geometry_default(wedge, wedge_half, 0.05, 'wedge centre to tip (half the block length)').
geometry_default(wedge, door_half_thickness, 0.02, 'half the door panel thickness').

geometry_value(wedge, door_width, _Tool, Target, _G, W) :-
    door_width_m(Target, W).
geometry_value(wedge, door_angle, _Tool, Target, _G, A) :-
    door_angle(Target, A).
geometry_value(wedge, wedge_half, Tool, _Target, _G, V) :-
    nonvar(Tool),
    (   size(Tool, Sx, _, _)
    ->  true
    ;   block_length_m(Tool, Sx)
    ),
    V is Sx / 2.

%   relative_pose/5, proved on the state: R the distance from the hinge to the wedge's
%   centre; Phi the heading of (wedge - hinge) relative to the closed door;
%   Gap = R * (A - Phi) - length / 2 - door half thickness; Yaw the wedge's heading (its
%   tip's direction, +x of the block frame) minus the heading from the wedge towards the
%   closing door (the counter-clockwise tangent, Theta0 + Phi + pi/2), wrapped to
%   (-pi, pi], so that 0 = tip pointing at the door.
relative_pose(wedge, Tool, Door, G, wedge_pose(R, Gap, Yaw)) :-
    door_polar(Tool, Door, R, Phi, A),
    door_closed_heading(Door, Theta0),
    pose(Tool, _, _, _, Heading),
    memberchk(wedge_half=Half, G),
    memberchk(door_half_thickness=Thick, G),
    Gap is R * (A - Phi) - Half - Thick,
    Towards is Theta0 + Phi + pi / 2,
    wrap_angle(Heading - Towards, Yaw).

%   pose_target/5, proved on the state: place(X, Y, Heading), the wedge centre's world X
%   and Y and the world yaw of its tip, radians in (-pi, pi]; the door's opening is the
%   door as it stands when the trial starts.
pose_target(wedge, wedge_pose(R, Gap, Yaw), Door, G, place(X, Y, Heading)) :-
    hinge(Door, HX, HY),
    door_closed_heading(Door, Theta0),
    door_angle(Door, A),
    R > 0,
    memberchk(wedge_half=Half, G),
    memberchk(door_half_thickness=Thick, G),
    Phi is A - (Gap + Half + Thick) / R,
    X is HX + R * cos(Theta0 + Phi),
    Y is HY + R * sin(Theta0 + Phi),
    wrap_angle(Yaw + Theta0 + Phi + pi / 2, Heading).

                 /*******************************
                 *     SIZING A NEW BLOCK       *
                 *******************************/

%   A sizing context fact door_gap_m(Door, G), the gap under the door: a new block must
%   be higher to stop it, and a blunted tip lower, so that it slides under the door.
size_constraint(block, door_gap_m(_, G), [height > G, tip_height < G]).
