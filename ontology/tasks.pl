/*  Task literals: the state of the hook and wedge tasks, from primitive facts.

    Plain Prolog data loaded into the knowledge base by knowledge:load_ontology/1.
    Primitive facts are in world coordinates (metres, radians); see DESIGN.md and the
    shared vocabulary.
*/

primitive_predicate(pose/5).
primitive_predicate(size/4).
primitive_predicate(held/1).
primitive_predicate(tip_position/4).
primitive_predicate(tool_roll/2).
primitive_predicate(tube_mouth/4).
primitive_predicate(tube_length_m/2).
primitive_predicate(tube_inner_m/3).
primitive_predicate(hinge/3).
primitive_predicate(door_width_m/2).
primitive_predicate(door_closed_heading/2).
primitive_predicate(door_angle/2).
primitive_predicate(door_held/1).

task_predicate(hook, in_tube/2).
task_predicate(hook, out_of_tube/2).
task_predicate(wedge, door_open/1).
task_predicate(wedge, door_held/1).

%   task_roles(?Case, ?Target, ?Context): the object a tool acts on and the object or
%   place the action happens in (the shared vocabulary's names).
task_roles(hook, cube1, tube1).
task_roles(wedge, door1, floor1).

%   in_tube(?Object, ?Tube): an uncatalogued object (the cube) whose centre lies inside
%   the tube's inner box; the tube's axis runs along +x from its mouth.
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

%   door_open(?Door): the door stands open by more than 0.05 rad (about 3 degrees).
door_open(D) :-
    door_angle(D, A),
    A > 0.05.
