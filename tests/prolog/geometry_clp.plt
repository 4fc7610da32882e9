:- begin_tests(geometry_clp, [setup(load_default_ontology)]).

:- use_module(library(clpr)).
:- use_module('../../prolog/knowledge').
:- use_module('../../prolog/geometry_clp').

%   The simulated hook task: mouth at x = 0.70, tube 0.30 m, inner 4 x 5.5 cm, a 3 cm
%   cube at x = 0.90 (0.10 m from the far end).
hook_context_([ tube_mouth(tube1, 0.70, 0.0, 0.0), tube_length_m(tube1, 0.30),
                tube_inner_m(tube1, 0.04, 0.055), pose(cube1, 0.90, 0.0, -0.0125, 0.0),
                size(cube1, 0.03, 0.03, 0.03), hook_width_m(h, 0.01),
                handle_width_m(h, 0.01) ]).

wedge_context_([ hinge(door1, 0.0, 0.0), door_width_m(door1, 0.8),
                 door_closed_heading(door1, 0.0), door_angle(door1, 0.8) ]).

%   strictly_inside_(+Case, +Literals, +Pose, +Geometry): the pose satisfies every
%   definition with a margin of 1 mm (1 mrad): interior, not on a bound.
strictly_inside_(Case, Literals, Pose, Geometry) :-
    Pose =.. [F|Xs],
    forall(( member(L, Literals),
             member(Delta, [-0.001, 0.001]),
             nth1(I, Xs, _),
             perturb_(Xs, I, Delta, Xs1) ),
           ( Pose1 =.. [F|Xs1],
             spatial_holds(Case, L, Pose1, Geometry) )).

perturb_([X|Xs], 1, Delta, [Y|Xs]) :-
    !,
    Y is X + Delta.
perturb_([X|Xs], I, Delta, [X|Ys]) :-
    I1 is I - 1,
    perturb_(Xs, I1, Delta, Ys).

test(hook_behind_down_interior) :-
    hook_context_(Ctx),
    Req = [in_tube(h, tube1), behind(h, cube1), hook_down(h), centred_on(h, cube1)],
    solve_pose(hook, Req, [], Ctx, R),
    assertion(R = pose(hook_pose(_, _, _))),
    R = pose(P),
    pose_geometry(hook, h, cube1, Ctx, G),
    assertion(forall(member(L, Req), spatial_holds(hook, L, P, G))),
    assertion(strictly_inside_(hook, Req, P, G)),
    P = hook_pose(Dx, Dy, Roll),
    % behind: Dx in [0.015 + 0.005 + 0.005, 0.70 + 0.30 - 0.90 - 0.005] = [0.025, 0.095]
    assertion(abs(Dx - 0.06) < 1e-6),
    assertion(abs(Dy) < 1e-6),
    assertion(abs(Roll) < 1e-6).

test(negated_behind_puts_prong_in_front) :-
    hook_context_(Ctx),
    solve_pose(hook, [in_tube(h, tube1), hook_down(h)], [behind(h, cube1)], Ctx, R),
    R = pose(P),
    pose_geometry(hook, h, cube1, Ctx, G),
    assertion(\+ spatial_holds(hook, behind(h, cube1), P, G)),
    assertion(spatial_holds(hook, in_tube(h, tube1), P, G)),
    P = hook_pose(Dx, _, _),
    assertion(Dx < 0.025).

test(negated_disjunction_hook_flat) :-
    solve_pose(hook, [], [hook_flat(h), hook_down(h)], [], R),
    R = pose(hook_pose(_, _, Roll)),
    assertion(abs(Roll) > 0.35),
    assertion(abs(Roll) < 1.2).

test(behind_and_in_front_conflict) :-
    hook_context_(Ctx),
    solve_pose(hook, [in_tube(h, tube1), behind(h, cube1), hook_down(h), in_front(h, cube1)],
               [hook_flat(h)], Ctx, R),
    assertion(R == infeasible([behind(h, cube1), in_front(h, cube1)])).

test(required_and_negated_conflict) :-
    solve_pose(hook, [hook_down(h), behind(h, cube1)], [hook_down(h)], [], R),
    assertion(R == infeasible([hook_down(h), not(hook_down(h))])).

test(no_room_behind_cube_at_far_end) :-
    hook_context_(Ctx0),
    selectchk(pose(cube1, _, Y, Z, Yaw), Ctx0, pose(cube1, 0.985, Y, Z, Yaw), Ctx),
    solve_pose(hook, [in_tube(h, tube1), behind(h, cube1)], [], Ctx, R),
    assertion(R == infeasible([behind(h, cube1)])).

test(wedge_near_far_from_hinge_tip_towards) :-
    wedge_context_(Ctx),
    Req = [near(w, door1), far_from_hinge(w, door1), tip_towards(w, door1)],
    solve_pose(wedge, Req, [], Ctx, R),
    R = pose(P),
    pose_geometry(wedge, w, door1, Ctx, G),
    assertion(strictly_inside_(wedge, Req, P, G)),
    P = wedge_pose(Rad, Gap, Yaw),
    assertion(abs(Rad - 0.625) < 1e-6),
    assertion(abs(Gap - 0.05) < 1e-6),
    assertion(abs(Yaw) < 1e-6).

test(wedge_near_and_far_conflict) :-
    wedge_context_(Ctx),
    solve_pose(wedge, [near(w, door1), tip_away(w, door1), far(w, door1)], [], Ctx, R),
    assertion(R == infeasible([near(w, door1), far(w, door1)])).

test(unknown_spatial_literal, [error(domain_error(spatial_literal(hook), on_top(h, cube1)))]) :-
    solve_pose(hook, [on_top(h, cube1)], [], [], _).

test(pose_constraints_then_search) :-
    pose_constraints(hook, [behind(h, cube1)], [], [], P),
    !,
    P = hook_pose(Dx, _, _),
    inf(Dx, I),
    sup(Dx, S),
    assertion(abs(I - 0.025) < 1e-9),
    assertion(abs(S - 0.07) < 1e-9),
    pose_search(P, G),
    assertion(G = hook_pose(0.0475, 0.0, 0.0)).

test(size_long_handle_for_long_tube) :-
    solve_size(hook, hook, [hook(t), hook_like(t), handle_length(t, long), hook_side(t, right),
                      hook_length(t, long), handle_width(t, thin)],
               [tube_length_m(tube1, 0.45), tube_inner_m(tube1, 0.04, 0.055),
                max_tool_length(0.70), min_wall_m(0.004)], R),
    assertion(R = dims(_)),
    R = dims(D),
    memberchk(handle_length=HL, D),
    memberchk(handle_width=HW, D),
    memberchk(hook_length=KL, D),
    memberchk(hook_side=Side, D),
    memberchk(hook_angle_deg=Ang, D),
    % long handle, >= 0.45 + 0.05 reach margin, =< 0.70: midpoint 0.60
    assertion(abs(HL - 0.60) < 1e-9),
    assertion(HW >= 0.006), assertion(HW < 0.012),
    assertion(KL >= 0.025), assertion(HW + KL + 0.005 =< 0.04),
    assertion(Side == right),
    assertion(Ang == 90).

test(size_medium_handle_does_not_reach_in_long_tube) :-
    solve_size(hook, hook, [hook(t), handle_length(t, medium)],
               [tube_length_m(tube1, 0.45), max_tool_length(0.70)], R),
    assertion(R == infeasible([handle_length(t, medium), tube_length_m(tube1, 0.45)])).

test(size_long_handle_too_long_to_hold) :-
    solve_size(hook, hook, [hook(t), handle_length(t, long), hook_side(t, left)],
               [max_tool_length(0.3)], R),
    assertion(R == infeasible([handle_length(t, long), max_tool_length(0.3)])).

test(size_kind_conflict) :-
    solve_size(hook, stick, [hook(t), handle_length(t, short)], [], R),
    assertion(R == infeasible([hook(t)])).

test(size_hook_angle_whole_degrees) :-
    solve_size(hook, hook, [hook_angle(t, obtuse)], [], dims(D)),
    memberchk(hook_angle_deg=A, D),
    assertion(A == 128).

test(size_wedge_long_above_one) :-
    solve_size(wedge, block, [block(w), shape(w, triangular_prism), block_length(w, long),
                       mechanical_advantage(w, above_one)],
               [door_gap_m(door1, 0.01), min_wall_m(0.004)], R),
    assertion(R == dims([length=0.16, width=0.085, height=0.0475, tip_height=0.0024,
                         shape=triangular_prism])).

%   A new wedge's tip is blunted: at least min_tip_height_m (two nozzle widths), below
%   its back height and below the door's gap, so that it slides under the door.
test(size_wedge_tip_blunted) :-
    solve_size(wedge, block, [shape(w, triangular_prism), block_length(w, long)],
               [door_gap_m(door1, 0.002)], dims(D)),
    memberchk(tip_height=T, D),
    memberchk(height=H, D),
    assertion(T >= 0.0008),
    assertion(T < 0.002),
    assertion(T < H).

test(size_wedge_tip_bounds_posted) :-
    size_constraints(wedge, block, [shape(w, triangular_prism)], [door_gap_m(door1, 0.01)], D),
    memberchk(tip_height=T, D),
    inf(T, Lo),
    sup(T, Hi),
    assertion(Lo =:= 0.0008),
    assertion(Hi =:= 0.004),
    assertion(\+ { T >= 0.01 }),
    assertion(\+ { T < 0.0008 }).

%   A context fact min_tip_height_m(M) overrides the default of two nozzle widths.
test(size_wedge_tip_minimum_from_context) :-
    solve_size(wedge, block, [shape(w, triangular_prism)],
               [door_gap_m(door1, 0.01), min_tip_height_m(0.003)], dims(D)),
    memberchk(tip_height=T, D),
    assertion(T >= 0.003),
    assertion(T =< 0.004).

%   A door gap lower than the printable tip: no new wedge.
test(size_wedge_tip_gap_below_printable) :-
    solve_size(wedge, block, [shape(w, triangular_prism)], [door_gap_m(door1, 0.0005)], R),
    assertion(R == infeasible([shape(w, triangular_prism), door_gap_m(door1, 0.0005)])).

%   A box or a cylinder has no tip.
test(size_box_has_no_tip) :-
    forall(member(S, [box, cylinder]),
           ( solve_size(wedge, block, [shape(w, S)], [door_gap_m(door1, 0.01)], dims(D)),
             memberchk(tip_height=T, D),
             assertion(T =:= 0) )).

%   Left to the search, the shape is a prism (the first choice), blunted as well.
test(size_block_unbound_shape_blunted) :-
    solve_size(wedge, block, [block_length(w, long)], [door_gap_m(door1, 0.01)], dims(D)),
    assertion(memberchk(shape=triangular_prism, D)),
    memberchk(tip_height=T, D),
    assertion(T >= 0.0008).

test(size_wedge_gap_too_high) :-
    solve_size(wedge, block, [shape(w, triangular_prism), block_height(w, low)],
               [door_gap_m(door1, 0.05)], R),
    assertion(R == infeasible([block_height(w, low), door_gap_m(door1, 0.05)])).

%   The strength check's thickening: a handle at least W wide, within its literals.
test(size_min_handle_width) :-
    solve_size(hook, hook, [handle_length(t, long), handle_width(t, thin)],
               [tube_inner_m(tube1, 0.04, 0.055), min_handle_width_m(0.0101)], dims(D)),
    memberchk(handle_width=W, D),
    assertion(W >= 0.0101),
    assertion(W < 0.012).

test(size_min_handle_width_infeasible) :-
    solve_size(hook, hook, [handle_width(t, thin)], [min_handle_width_m(0.0159)], R),
    assertion(R == infeasible([handle_width(t, thin), min_handle_width_m(0.0159)])).

test(size_cylinder_width_equals_length) :-
    solve_size(wedge, block, [shape(w, cylinder), block_length(w, short)], [], dims(D)),
    memberchk(length=L, D),
    memberchk(width=W, D),
    assertion(L =:= W).

test(size_unknown_value, [error(domain_error(structural_literal(hook), handle_length(t, huge)))]) :-
    solve_size(hook, hook, [handle_length(t, huge)], [], _).

test(size_spatial_literals_ignored) :-
    solve_size(hook, hook, [handle_length(t, short), behind(t, cube1), in_tube(t, tube1)], [], R),
    assertion(R = dims(_)).

%   Law: for every choice of up to two required hook literals and one negated one,
%   solve_pose/5 either returns a pose where the required literals hold and the negated
%   one does not, or a conflict that is infeasible and minimal (dropping any member
%   makes the rest feasible).
test(pose_law_all_small_combinations) :-
    hook_context_(Ctx),
    Lits = [in_tube(h, tube1), behind(h, cube1), in_front(h, cube1), centred_on(h, cube1),
            hook_down(h), hook_flat(h)],
    pose_geometry(hook, h, cube1, Ctx, G),
    forall(( sublist_(Lits, Req), length(Req, NR), NR =< 2,
             ( Neg = [] ; member(N, Lits), Neg = [N] ) ),
           pose_law_(Req, Neg, Ctx, G)).

pose_law_(Req, Neg, Ctx, G) :-
    solve_pose(hook, Req, Neg, Ctx, R),
    (   R = pose(P)
    ->  assertion(forall(member(L, Req), spatial_holds(hook, L, P, G))),
        assertion(forall(member(L, Neg), \+ spatial_holds(hook, L, P, G)))
    ;   R = infeasible(Conflict),
        split_conflict_(Conflict, CR, CN),
        solve_pose(hook, CR, CN, Ctx, R1),
        assertion(R1 = infeasible(_)),
        forall(select(_, Conflict, Rest),
               ( split_conflict_(Rest, RR, RN),
                 solve_pose(hook, RR, RN, Ctx, R2),
                 assertion(R2 = pose(_)) ))
    ).

split_conflict_([], [], []).
split_conflict_([not(L)|Cs], Rs, [L|Ns]) :-
    !,
    split_conflict_(Cs, Rs, Ns).
split_conflict_([L|Cs], [L|Rs], Ns) :-
    split_conflict_(Cs, Rs, Ns).

sublist_([], []).
sublist_([X|Xs], [X|Ys]) :-
    sublist_(Xs, Ys).
sublist_([_|Xs], Ys) :-
    sublist_(Xs, Ys).

%   Law (round trip): a tool sized by solve_size/5 for two qualitative values has, when
%   its dimensions are read back through the ontology's ranges, exactly those values.
test(size_round_trip_hook) :-
    Props = [handle_length, handle_width, hook_length, hook_width, hook_angle],
    forall(( select(P1, Props, Rest), member(P2, Rest), P1 @< P2,
             shared_clause(qualitative_range(P1, V1, _, _, _), true),
             shared_clause(qualitative_range(P2, V2, _, _, _), true) ),
           ( L1 =.. [P1, t, V1],
             L2 =.. [P2, t, V2],
             solve_size(hook, hook, [hook(t), L1, L2, hook_side(t, left)], [], dims(D)),
             hook_catalogue_(t, D, Facts),
             assertion(case_prove(hook, L1, Facts)),
             assertion(case_prove(hook, L2, Facts)),
             assertion(case_prove(hook, hook_side(t, left), Facts)) )).

test(size_round_trip_block) :-
    Props = [block_length, block_width, block_height, mechanical_advantage],
    forall(( select(P1, Props, Rest), member(P2, Rest), P1 @< P2,
             shared_clause(qualitative_range(P1, V1, _, _, _), true),
             shared_clause(qualitative_range(P2, V2, _, _, _), true),
             member(Shape, [triangular_prism, box]) ),
           ( L1 =.. [P1, w, V1],
             L2 =.. [P2, w, V2],
             solve_size(wedge, block, [shape(w, Shape), L1, L2], [], R),
             (   R = dims(D)
             ->  block_catalogue_(w, D, Facts),
                 assertion(case_prove(wedge, L1, Facts)),
                 assertion(case_prove(wedge, L2, Facts)),
                 assertion(case_prove(wedge, shape(w, Shape), Facts))
             ;   % a long block (>= 0.12 m) would need a height above the 0.08 m maximum
                 assertion(R == infeasible([L1, L2])),
                 assertion([L1, L2] == [block_length(w, long),
                                        mechanical_advantage(w, below_one)])
             ) )).

hook_catalogue_(T, D, [ object_kind(T, hook), handle_length_m(T, HL), handle_width_m(T, HW),
                        hook_length_m(T, KL), hook_width_m(T, KW), hook_side_is(T, S),
                        hook_angle_deg(T, A) ]) :-
    memberchk(handle_length=HL, D), memberchk(handle_width=HW, D),
    memberchk(hook_length=KL, D), memberchk(hook_width=KW, D),
    memberchk(hook_side=S, D), memberchk(hook_angle_deg=A, D).

block_catalogue_(W, D, [ object_kind(W, block), block_shape(W, S), block_length_m(W, L),
                         block_width_m(W, Wd), block_height_m(W, H) ]) :-
    memberchk(shape=S, D), memberchk(length=L, D),
    memberchk(width=Wd, D), memberchk(height=H, D).

%   pose_reachable/5: the hook's reach is its handle length (catalogue) from the mouth,
%   dx_reach = 0.70 + L + 0.04 - 0.005 - 0.90 = L - 0.165 in the context above.
test(short_handle_cannot_reach_behind_the_cube) :-
    hook_context_(Ctx),
    Req = [in_tube(h, tube1), behind(h, cube1), hook_down(h)],
    pose_reachable(hook, h, Req, [handle_length_m(h, 0.15)|Ctx], R),
    assertion(R = unreachable([behind(h, cube1)], [param(dx_reach, _, _)])),
    R = unreachable(_, [param(dx_reach, V, _)]),
    assertion(abs(V - (-0.015)) < 1e-9).

test(long_enough_handle_reaches_and_the_pose_is_within_reach) :-
    hook_context_(Ctx),
    Req = [in_tube(h, tube1), behind(h, cube1), hook_down(h)],
    pose_reachable(hook, h, Req, [handle_length_m(h, 0.20)|Ctx], R),
    assertion(R = reachable(hook_pose(_, _, _))),
    R = reachable(hook_pose(Dx, _, _)),
    assertion(Dx >= 0.025),
    assertion(Dx =< 0.035 + 1e-9).

test(in_front_needs_no_reach) :-
    hook_context_(Ctx),
    pose_reachable(hook, h, [in_front(h, cube1)], [handle_length_m(h, 0.15)|Ctx], R),
    assertion(R = reachable(_)).

test(wedge_geometry_cannot_tell) :-
    wedge_context_(Ctx),
    pose_reachable(wedge, w, [near(w, door1), far_from_hinge(w, door1)], Ctx, R),
    assertion(R == undecided).

:- end_tests(geometry_clp).
