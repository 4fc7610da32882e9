:- begin_tests(abstract_state, [setup(load_default_ontology)]).

:- use_module('../../prolog/knowledge').
:- use_module('../../prolog/abstract_state').

%   A hook-case scene: tube mouth at x = 0.70, 0.30 m long, inner 4 x 5.5 cm; cube at
%   x = 0.90 inside; a hook held with its prong 5 cm past the cube, pointing down.
hook_catalogue_([ object_kind(hook_a2, hook), handle_length_m(hook_a2, 0.30),
                  handle_width_m(hook_a2, 0.01), hook_length_m(hook_a2, 0.03),
                  hook_width_m(hook_a2, 0.01), hook_side_is(hook_a2, right),
                  hook_angle_deg(hook_a2, 90),
                  object_kind(hook_b5, stick), handle_length_m(hook_b5, 0.5),
                  handle_width_m(hook_b5, 0.008), hook_side_is(hook_b5, none) ]).

tube_([ tube_mouth(tube1, 0.70, 0.0, 0.0), tube_length_m(tube1, 0.30),
        tube_inner_m(tube1, 0.04, 0.055) ]).

hook_scene_(TipX, Roll, CubeX, Facts) :-
    hook_catalogue_(Cat),
    tube_(Tube),
    append([Cat, Tube,
            [ pose(cube1, CubeX, 0.0, -0.0125, 0.0), size(cube1, 0.03, 0.03, 0.03),
              held(hook_a2), tip_position(hook_a2, TipX, 0.002, -0.01),
              tool_roll(hook_a2, Roll) ]],
           Facts).

test(hook_behind_down) :-
    hook_scene_(0.95, 0.1, 0.90, Facts),
    abstract_state(hook, Facts, A),
    sort([ behind(hook_a2, cube1), centred_on(hook_a2, cube1),
                     handle_length(hook_a2, medium), handle_length(hook_b5, long),
                     handle_width(hook_a2, thin), handle_width(hook_b5, thin),
                     hook(hook_a2), hook_angle(hook_a2, right), hook_down(hook_a2),
                     hook_length(hook_a2, long), hook_like(hook_a2), hook_like(hook_b5),
                     hook_side(hook_a2, right), hook_width(hook_a2, wide),
                     in_tube(cube1, tube1), in_tube(hook_a2, tube1), stick(hook_b5),
                     tool(hook_a2), tool(hook_b5) ], Expected),
    assertion(A == Expected).

test(hook_in_front_flat) :-
    hook_scene_(0.80, 1.5, 0.90, Facts),
    abstract_state(hook, Facts, A),
    assertion(memberchk(in_front(hook_a2, cube1), A)),
    assertion(memberchk(hook_flat(hook_a2), A)),
    assertion(\+ memberchk(behind(hook_a2, cube1), A)),
    assertion(\+ memberchk(hook_down(hook_a2), A)).

test(cube_pulled_out_tool_outside) :-
    hook_scene_(0.60, 0.0, 0.55, Facts),
    abstract_state(hook, Facts, A),
    assertion(memberchk(out_of_tube(cube1, tube1), A)),
    assertion(\+ memberchk(in_tube(cube1, tube1), A)),
    assertion(\+ memberchk(hook_down(hook_a2), A)).

test(hook_pose_numbers) :-
    hook_scene_(0.95, 0.1, 0.90, Facts),
    pose_numbers(hook, hook_a2, Facts, hook_pose(Dx, Dy, Roll)),
    assertion(abs(Dx - 0.05) < 1e-9),
    assertion(abs(Dy - 0.002) < 1e-9),
    assertion(Roll == 0.1).

test(pose_numbers_missing_fact, [fail]) :-
    pose_numbers(hook, hook_a2, [tip_position(hook_a2, 0.9, 0, 0)], _).

%   Wedge case: hinge at the origin, the closed door points along +x, open 0.45 rad.
%   wedge_a2 lies 0.6 m out at polar angle 0.1/0.6, its tip towards the door.
wedge_scene_(Facts) :-
    Phi is atan2(0.1, 0.6),
    Heading is Phi + pi / 2,
    Facts = [ object_kind(wedge_a2, block), block_shape(wedge_a2, triangular_prism),
              block_length_m(wedge_a2, 0.15), block_width_m(wedge_a2, 0.05),
              block_height_m(wedge_a2, 0.03),
              object_kind(box_a1, block), block_shape(box_a1, box),
              block_length_m(box_a1, 0.05), block_width_m(box_a1, 0.05),
              block_height_m(box_a1, 0.05), pose(box_a1, 2.0, 2.0, 0.0, 0.0),
              size(box_a1, 0.05, 0.05, 0.05),
              hinge(door1, 0.0, 0.0), door_width_m(door1, 0.8),
              door_closed_heading(door1, 0.0), door_angle(door1, 0.45),
              pose(wedge_a2, 0.6, 0.1, 0.0, Heading), size(wedge_a2, 0.15, 0.05, 0.03) ].

test(wedge_pose_numbers) :-
    wedge_scene_(Facts),
    pose_numbers(wedge, wedge_a2, Facts, wedge_pose(R, Gap, Yaw)),
    ExpectedR is sqrt(0.37),
    ExpectedGap is ExpectedR * (0.45 - atan2(0.1, 0.6)) - 0.075 - 0.02,
    assertion(abs(R - ExpectedR) < 1e-9),
    assertion(abs(Gap - ExpectedGap) < 1e-9),
    assertion(abs(Yaw) < 1e-9).

test(wedge_state) :-
    wedge_scene_(Facts),
    abstract_state(wedge, [door_held(door1)|Facts], A),
    sort([ block(box_a1), block(wedge_a2), door_held(door1), door_open(door1),
                     far_from_hinge(wedge_a2, door1), near(wedge_a2, door1),
                     object(box_a1), object(wedge_a2),
                     block_height(box_a1, high), block_height(wedge_a2, low),
                     block_length(box_a1, short), block_length(wedge_a2, long),
                     block_width(box_a1, narrow), block_width(wedge_a2, narrow),
                     mechanical_advantage(box_a1, below_one),
                     mechanical_advantage(wedge_a2, above_one),
                     shape(box_a1, box), shape(wedge_a2, triangular_prism),
                     tip_towards(wedge_a2, door1) ], Expected),
    assertion(A == Expected).

test(wedge_reversed_is_tip_away) :-
    wedge_scene_(Facts0),
    selectchk(pose(wedge_a2, X, Y, Z, H0), Facts0, pose(wedge_a2, X, Y, Z, H), Facts),
    H is H0 + pi,
    abstract_state(wedge, Facts, A),
    assertion(memberchk(tip_away(wedge_a2, door1), A)),
    assertion(\+ memberchk(tip_towards(wedge_a2, door1), A)).

test(bad_case, [error(existence_error(case, door))]) :-
    abstract_state(door, [], _).

test(non_ground_fact, [error(instantiation_error)]) :-
    abstract_state(hook, [pose(cube1, _, 0, 0, 0)], _).

test(hook_pose_world_inverts_pose_numbers) :-
    hook_scene_(0.95, 0.1, 0.90, Facts),
    pose_world(hook, hook_a2, Facts, hook_pose(0.04, -0.01, 0.2), tip(X, Y, Roll)),
    assertion(abs(X - 0.94) < 1e-9),
    assertion(abs(Y + 0.01) < 1e-9),
    assertion(Roll == 0.2).

%   Law: pose_world/5 then pose_numbers/4 gives the pose back, for a grid of wedge poses
%   and door headings.
test(wedge_pose_world_round_trip) :-
    wedge_scene_(Facts0),
    forall(( member(Theta0, [0.0, 1.2, -2.5, 3.0]),
             member(R, [0.2, 0.45, 0.7]),
             member(Gap, [0.0, 0.05, 0.2]),
             member(Yaw, [0.0, 0.25, -3.0, 3.1]) ),
           ( selectchk(door_closed_heading(door1, _), Facts0,
                       door_closed_heading(door1, Theta0), Facts1),
             pose_world(wedge, wedge_a2, Facts1, wedge_pose(R, Gap, Yaw), place(X, Y, H)),
             selectchk(pose(wedge_a2, _, _, Z, _), Facts1, pose(wedge_a2, X, Y, Z, H), Facts),
             pose_numbers(wedge, wedge_a2, Facts, wedge_pose(R1, Gap1, Yaw1)),
             assertion(abs(R1 - R) < 1e-9),
             assertion(abs(Gap1 - Gap) < 1e-9),
             assertion(abs(sin(Yaw1 - Yaw)) + abs(cos(Yaw1 - Yaw) - 1) < 1e-9) )).

:- end_tests(abstract_state).
