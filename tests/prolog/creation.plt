:- begin_tests(creation).

:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module('fixtures/primitive_fixtures').

%   The hook demonstration's version space after the short-handled hook_a1 failed: a
%   negative that violates only handle_length(T, medium), which h_g then holds.
short_hook_failed_vs_(VS) :-
    fixture_demonstration_vs(hook, VS0, _),
    vs_examples(VS0, [E], _),
    fixture_variant_example(E, hook_a1,
                            [handle_length(hook_a1, medium)-handle_length(hook_a1, short)],
                            Neg),
    vs_update(VS0, neg(Neg), VS).

%   ... and then the left-sided hook_a4 failed too: h_g also holds hook_side(T, right).
left_hook_failed_vs_(VS) :-
    short_hook_failed_vs_(VS0),
    vs_examples(VS0, [E], _),
    fixture_variant_example(E, hook_a4, [hook_side(hook_a4, right)-hook_side(hook_a4, left)],
                            Neg),
    vs_update(VS0, neg(Neg), VS).

%   A wedge demonstration with a medium wedge (the fixture's wedge_a2 made medium),
%   and the same after a short wedge, otherwise identical, failed.
medium_wedge_vs_(VS) :-
    medium_wedge_example_(E),
    vs_init(E, VS).

short_wedge_failed_vs_(VS) :-
    medium_wedge_example_(E),
    vs_init(E, VS0),
    fixture_variant_example(E, wedge_s,
                            [block_length(wedge_s, medium)-block_length(wedge_s, short)],
                            Neg),
    vs_update(VS0, neg(Neg), VS).

medium_wedge_example_(E) :-
    fixture_demonstration_vs(wedge, VS, _),
    vs_examples(VS, [E0], _),
    fixture_variant_example(E0, wedge_m,
                            [block_length(wedge_m, long)-block_length(wedge_m, medium)], E).

replaced_(candidate(R, _, _, _), R).
is_stick_(stick(_)).
instance_(candidate(_, _, I, _), I).

longer_tube_([tube_length_m(tube1, 0.45), tube_inner_m(tube1, 0.08, 0.07)]).
same_tube_([tube_length_m(tube1, 0.30), tube_inner_m(tube1, 0.08, 0.07)]).

dim_(Dims, Name, Value) :-
    memberchk(Name=Value, Dims).

                 /*******************************
                 *          CANDIDATES          *
                 *******************************/

test(handle_length_first_long_before_short) :-
    short_hook_failed_vs_(VS),
    vs_bounds(VS, _, HG),
    assertion(HG =@= (tool_pose(T0, _, _) :- handle_length(T0, medium))),
    creation_candidates(VS, [], Cs),
    Cs = [C1, C2, C3|_],
    assertion(C1 =@= candidate(handle_length(T, medium), any_length(T), handle_length(T, long),
                               [tool(T), hook_like(T), hook(T), handle_length(T, long),
                                handle_width(T, thick), hook_length(T, long),
                                hook_width(T, wide), hook_side(T, right),
                                hook_angle(T, right)])),
    assertion(C2 = candidate(handle_length(_, medium), _, handle_length(_, short), _)),
    replaced_(C3, R3),
    assertion(R3 \= handle_length(_, _)).

test(candidates_follow_the_ontology_operator_order) :-
    short_hook_failed_vs_(VS),
    creation_candidates(VS, [], Cs),
    maplist(instance_, Cs, Instances),
    assertion(Instances =@= [handle_length(T1, long), handle_length(T2, short),
                             hook_length(T3, short), handle_width(T4, thin),
                             hook_width(T5, narrow), hook_side(T6, left),
                             hook_angle(T7, acute), hook_angle(T8, obtuse), stick(T9)]),
    assertion(maplist(var, [T1, T2, T3, T4, T5, T6, T7, T8, T9])).

test(properties_in_hg_come_before_the_others) :-
    left_hook_failed_vs_(VS),
    creation_candidates(VS, [], Cs),
    maplist(replaced_, Cs, Replaced),
    assertion(Replaced =@= [handle_length(A, medium), handle_length(B, medium),
                            hook_side(C, right), hook_length(D, long),
                            handle_width(E, thick), hook_width(F, wide),
                            hook_angle(G, right), hook_angle(H, right), hook(I)]),
    assertion(maplist(var, [A, B, C, D, E, F, G, H, I])).

test(excluded_property_is_left_out) :-
    short_hook_failed_vs_(VS),
    creation_candidates(VS, [exclude([handle_length(_, medium)])], Cs),
    maplist(replaced_, Cs, Replaced),
    assertion(\+ memberchk(handle_length(_, _), Replaced)),
    Cs = [First|_],
    assertion(First = candidate(hook_length(_, long), any_hook_length(_),
                                hook_length(_, short), _)).

test(wedge_short_refuted_so_long_first) :-
    short_wedge_failed_vs_(VS),
    vs_bounds(VS, _, HG),
    assertion(HG =@= (tool_pose(W, _, _) :- block_length(W, medium))),
    creation_candidates(VS, [], [C1, C2|_]),
    assertion(C1 = candidate(block_length(_, medium), any_block_length(_),
                             block_length(_, long), _)),
    assertion(C2 = candidate(block_length(_, medium), any_block_length(_),
                             block_length(_, short), _)).

test(wedge_without_refutation_keeps_the_ontology_order) :-
    medium_wedge_vs_(VS),
    creation_candidates(VS, [], [C1, C2|_]),
    assertion(C1 = candidate(_, _, block_length(_, short), _)),
    assertion(C2 = candidate(_, _, block_length(_, long), _)).

test(negative_differing_in_two_properties_refutes_nothing) :-
    medium_wedge_example_(E),
    vs_init(E, VS0),
    fixture_variant_example(E, wedge_s,
                            [ block_length(wedge_s, medium)-block_length(wedge_s, short),
                              block_height(wedge_s, low)-block_height(wedge_s, high) ],
                            Neg),
    vs_update(VS0, neg(Neg), VS),
    creation_candidates(VS, [], [C1, C2|_]),
    assertion(C1 = candidate(block_length(_, medium), _, block_length(_, short), _)),
    assertion(C2 = candidate(block_length(_, medium), _, block_length(_, long), _)).

                 /*******************************
                 *           NEXT TOOL          *
                 *******************************/

test(longer_tube_creates_a_long_handle) :-
    short_hook_failed_vs_(VS),
    longer_tube_(Context),
    next_tool(hook, VS, [], Context, [], R),
    R = create(Replaced, General, Instance, Struct, Dims),
    assertion(Replaced-General-Instance =@=
              handle_length(T, medium)-any_length(T)-handle_length(T, long)),
    assertion(Struct =@= [tool(T), hook_like(T), hook(T), handle_length(T, long),
                          handle_width(T, thick), hook_length(T, long), hook_width(T, wide),
                          hook_side(T, right), hook_angle(T, right)]),
    dim_(Dims, handle_length, HL),
    assertion(HL >= 0.50),          % the tube's 0.45 m plus the 5 cm reach margin
    assertion(HL =< 0.70),          % and within the long range
    dim_(Dims, handle_width, HW),
    dim_(Dims, hook_length, KL),
    assertion(HW >= 0.012),         % thick
    assertion(HW + KL =< 0.065),    % turns inside the 7 cm tube, 5 mm clearance
    dim_(Dims, hook_side, Side),
    assertion(Side == right),
    dim_(Dims, hook_angle_deg, Angle),
    assertion(between(75, 105, Angle)).

test(tried_instance_moves_on_to_the_next_candidate) :-
    short_hook_failed_vs_(VS),
    same_tube_(Context),
    next_tool(hook, VS, [handle_length(_, long)], Context, [], R),
    R = create(Replaced, General, Instance, Struct, Dims),
    % short handles cannot reach into a 30 cm tube: the prong length comes next
    assertion(Replaced-General-Instance =@=
              hook_length(T, long)-any_hook_length(T)-hook_length(T, short)),
    assertion(memberchk(handle_length(T, medium), Struct)),
    dim_(Dims, hook_length, KL),
    assertion(KL >= 0.010),
    assertion(KL < 0.025),
    dim_(Dims, handle_length, HL),
    assertion(HL >= 0.35),
    assertion(HL < 0.45).

test(exhausted_when_every_candidate_is_tried_or_infeasible) :-
    short_hook_failed_vs_(VS),
    longer_tube_(Context),
    next_tool(hook, VS, [handle_length(_, long)], Context, [], R),
    assertion(R = exhausted(_)),
    R = exhausted(Skipped),
    length(Skipped, 9),
    Skipped = [First, Second|Rest],
    assertion(First = handle_length(_, long)-tried),
    assertion(Second = handle_length(_, short)-infeasible(_)),
    Second = _-infeasible(Conflict),
    assertion(memberchk(tube_length_m(tube1, 0.45), Conflict)),
    forall(member(_-Reason, Rest), assertion(Reason = infeasible(_))).

test(exhausted_when_every_instance_was_tried) :-
    short_hook_failed_vs_(VS),
    creation_candidates(VS, [], Cs),
    maplist(instance_, Cs, Tried),
    same_tube_(Context),
    next_tool(hook, VS, Tried, Context, [], R),
    assertion(R = exhausted(_)),
    R = exhausted(Skipped),
    findall(I, member(I-tried, Skipped), Again),
    assertion(Again =@= Tried).

test(wedge_creates_a_long_wedge) :-
    short_wedge_failed_vs_(VS),
    next_tool(wedge, VS, [], [], [], R),
    R = create(Replaced, General, Instance, Struct, Dims),
    assertion(Replaced-General-Instance =@=
              block_length(W, medium)-any_block_length(W)-block_length(W, long)),
    assertion(memberchk(shape(W, triangular_prism), Struct)),
    dim_(Dims, length, L),
    dim_(Dims, height, H),
    assertion(L >= 0.12),
    assertion(L =< 0.20),
    assertion(H < 0.04),            % low
    assertion(L / H > 1.0),         % mechanical advantage above one
    dim_(Dims, shape, Shape),
    assertion(Shape == triangular_prism).

%   A stick candidate drops the hook's prong literals, so it can be sized as a stick.
test(stick_candidate_is_sized_as_a_stick) :-
    short_hook_failed_vs_(VS),
    creation_candidates(VS, [], Cs),
    maplist(instance_, Cs, Tried0),
    exclude(is_stick_, Tried0, Tried),
    same_tube_(Context),
    next_tool(hook, VS, Tried, Context, [], R),
    assertion(R = create(hook(_), any_kind(_), stick(_), _, _)).

                 /*******************************
                 *   CATALOGUED OBJECTS FIRST   *
                 *******************************/

%   The longer tube (0.45 m) with the cube at its end, and the fixture's catalogue.
longer_tube_primitive_(P) :-
    fixture_catalogue(hook, C),
    append(C, [tube_mouth(tube1, 0.70, 0.0, 0.0), tube_length_m(tube1, 0.45),
               tube_inner_m(tube1, 0.08, 0.07), pose(cube1, 1.05, 0.0, -0.02, 0.0),
               size(cube1, 0.03, 0.03, 0.03)], P).

catalogued_name_(catalogued(O, _, _), O).

test(catalogue_long_handles_first_refuted_short_last) :-
    short_hook_failed_vs_(VS),
    longer_tube_primitive_(P),
    catalogue_first(hook, VS, P, [hook_a2], R),
    R = catalogue(Replaced, General, Items),
    assertion(Replaced =@= handle_length(_, medium)),
    assertion(General =@= any_length(_)),
    maplist(catalogued_name_, Items, Names),
    % hook_a2 tried already; hook_a4 has the replaced (medium) value: neither is new.
    % The long ones by name (the planner's order), the short hook (refuted during
    % tool-use learning) last.
    assertion(Names == [hook_a3, hook_a5, hook_a1]),
    Items = [catalogued(hook_a3, Value, Use)|_],
    assertion(Value == handle_length(hook_a3, long)),
    assertion(Use = exploit(hook_a3, _, hook_pose(_, _, _), _)).

test(catalogue_needs_hg_without_the_replaced_literal) :-
    left_hook_failed_vs_(VS),
    longer_tube_primitive_(P),
    catalogue_first(hook, VS, P, [], catalogue(_, _, Items)),
    maplist(catalogued_name_, Items, Names),
    % h_g keeps hook_side(T, right): the stick (no side) is no longer admitted.
    assertion(Names == [hook_a3, hook_a1]).

test(catalogue_wedge_in_the_ontology_order) :-
    medium_wedge_vs_(VS),
    fixture_primitive(wedge, P),
    catalogue_first(wedge, VS, P, [wedge_a1], catalogue(Replaced, _, Items)),
    assertion(Replaced =@= block_length(_, medium)),
    maplist(catalogued_name_, Items, Names),
    % Short before long, as the ontology lists them (no negative refuted either);
    % wedge_a1 excluded.
    assertion(Names == [cylinder_b1, wedge_a2]).

test(catalogue_wedge_refuted_short_last) :-
    short_wedge_failed_vs_(VS),
    fixture_primitive(wedge, P),
    catalogue_first(wedge, VS, P, [], catalogue(_, _, Items)),
    maplist(catalogued_name_, Items, Names),
    assertion(Names == [wedge_a2, cylinder_b1, wedge_a1]).

:- end_tests(creation).
