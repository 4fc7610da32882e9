:- begin_tests(version_space).

%   Hook-case examples in the shared vocabulary: Tool with a handle length
%   class, its length in metres, the hook side and the spatial literals of
%   the trial.
hook_example(Tool, HL, HLm, Side, Spatial, E) :-
    Lits0 = [ tool(Tool), hook_like(Tool), hook(Tool), handle_length(Tool, HL),
              handle_width(Tool, thin), hook_length(Tool, long), hook_width(Tool, wide),
              hook_side(Tool, Side), hook_angle(Tool, right), handle_length_m(Tool, HLm),
              in_tube(Tool, tube1), in_tube(cube1, tube1) | Spatial ],
    clause_head_body(E, tool_pose(Tool, cube1, tube1), Lits0).

demo(E) :-
    hook_example(hook_a2, medium, 0.35, right,
                 [behind(hook_a2, cube1), hook_down(hook_a2), centred_on(hook_a2, cube1)], E).

demo_vs(VS) :-
    demo(E),
    vs_init(E, VS).

test(init_roles) :-
    demo_vs(VS),
    vs_bounds(VS, HS, HG),
    HG = tool_pose(T, C, X),
    assertion(maplist(var, [T, C, X])),
    assertion(HS = (tool_pose(T, C, X) :- _)),
    clause_head_body(HS, _, Body),
    assertion(memberchk(behind(T, C), Body)),
    assertion(memberchk(in_tube(C, X), Body)),
    assertion(memberchk(handle_length_m(T, 0.35), Body)),
    vs_unknown(VS, U),
    assertion(length(U, 15)),
    vs_examples(VS, Pos, Neg),
    assertion(length(Pos, 1)),
    assertion(Neg == []).

test(init_bounds_share_head) :-
    demo_vs(VS),
    vs_bounds(VS, HS, H2),
    HS = (H1 :- _),
    assertion(H1 == H2).

%   A positive with a long handle: handle_length/2 leaves h_s, the metres
%   become a range, one unknown literal fewer.
test(positive_drops_handle_length) :-
    demo_vs(VS0),
    hook_example(hook_a3, long, 0.5, right,
                 [behind(hook_a3, cube1), hook_down(hook_a3), centred_on(hook_a3, cube1)], E),
    vs_update(VS0, pos(E), VS),
    vs_bounds(VS, HS, _),
    clause_head_body(HS, tool_pose(T, _, _), Body),
    assertion(\+ memberchk(handle_length(_, _), Body)),
    assertion(( member(handle_length_m(T1, L), Body), T1 == T,
                member(in_range(L1, Lo, Hi), Body), L1 == L, Lo =:= 0.35, Hi =:= 0.5 )),
    vs_unknown(VS0, U0),
    vs_unknown(VS, U),
    length(U0, N0),
    length(U, N),
    assertion(N =:= N0 - 1),
    assertion(\+ memberchk(in_range(_, _, _), U)),
    assertion(vs_covers(VS, hs, E)).

%   A negative that violates only behind/2 (the prong was in front of the
%   cube) puts behind/2 into h_g.
test(negative_in_front_specialises_hg) :-
    demo_vs(VS0),
    hook_example(hook_a2, medium, 0.35, right,
                 [in_front(hook_a2, cube1), hook_down(hook_a2), centred_on(hook_a2, cube1)], N),
    vs_update(VS0, neg(N), VS),
    vs_bounds(VS, _, HG),
    assertion(HG =@= (tool_pose(T, C, _) :- behind(T, C))),
    vs_unknown(VS0, U0),
    vs_unknown(VS, U),
    length(U0, N0),
    length(U, N1),
    assertion(N1 =:= N0 - 1),
    assertion(\+ ( member(L, U), L = behind(_, _) )),
    assertion(\+ vs_covers(VS, hg, N)),
    vs_examples(VS, _, Neg),
    assertion(Neg == [N]).

%   Violating behind/2 and hook_down/2 at once needs one literal only: the
%   first one the negative violates.
test(negative_smallest_specialisation) :-
    demo_vs(VS0),
    hook_example(hook_a2, medium, 0.35, right,
                 [in_front(hook_a2, cube1), hook_flat(hook_a2), centred_on(hook_a2, cube1)], N),
    vs_update(VS0, neg(N), VS),
    vs_bounds(VS, _, HG),
    assertion(HG =@= (tool_pose(T, C, _) :- behind(T, C))).

%   Two negatives with different causes: h_g needs both literals.
test(two_negatives_two_literals) :-
    demo_vs(VS0),
    hook_example(hook_a2, medium, 0.35, right,
                 [in_front(hook_a2, cube1), hook_down(hook_a2), centred_on(hook_a2, cube1)], N1),
    hook_example(hook_a2, medium, 0.35, right,
                 [behind(hook_a2, cube1), hook_flat(hook_a2), centred_on(hook_a2, cube1)], N2),
    vs_update(VS0, neg(N1), VS1),
    vs_update(VS1, neg(N2), VS),
    vs_bounds(VS, _, HG),
    assertion(HG =@= (tool_pose(T, C, _) :- behind(T, C), hook_down(T))).

test(negative_outside_hg_only_stored) :-
    demo_vs(VS0),
    hook_example(hook_a2, medium, 0.35, right,
                 [in_front(hook_a2, cube1), hook_down(hook_a2), centred_on(hook_a2, cube1)], N1),
    vs_update(VS0, neg(N1), VS1),
    hook_example(hook_b1, medium, 0.35, right,
                 [in_front(hook_b1, cube1), hook_flat(hook_b1), centred_on(hook_b1, cube1)], N2),
    vs_update(VS1, neg(N2), VS),
    vs_bounds(VS1, _, HG1),
    vs_bounds(VS, _, HG),
    assertion(HG =@= HG1),
    vs_examples(VS, _, Neg),
    assertion(Neg == [N1, N2]),
    vs_notes(VS, Notes),
    assertion(Notes == []).

%   The demonstration repeated as a failure: h_s covers it, it is noise.
test(negative_covered_by_hs_is_noise) :-
    demo_vs(VS0),
    demo(E),
    vs_update(VS0, neg(E), VS),
    vs_bounds(VS0, _, HG0),
    vs_bounds(VS, _, HG),
    assertion(HG =@= HG0),
    vs_notes(VS, Notes),
    assertion(Notes == [noisy_negative(E)]).

%   A positive that violates h_g: the literal is dropped and the space
%   records the inconsistency; the stored negative is now covered by h_s
%   (behind/2 left h_s too), so it becomes noise (newest note first).
test(positive_weakens_hg) :-
    demo_vs(VS0),
    hook_example(hook_a2, medium, 0.35, right,
                 [in_front(hook_a2, cube1), hook_down(hook_a2), centred_on(hook_a2, cube1)], N),
    vs_update(VS0, neg(N), VS1),
    hook_example(hook_a3, medium, 0.35, right,
                 [in_front(hook_a3, cube1), hook_down(hook_a3), centred_on(hook_a3, cube1)], P),
    vs_update(VS1, pos(P), VS),
    vs_bounds(VS, _, HG),
    assertion(HG =@= tool_pose(_, _, _)),
    vs_notes(VS, Notes),
    assertion(Notes = [noisy_negative(N), hg_weakened(P, [behind(_, _)])]).

test(update_leaves_input_unchanged) :-
    demo_vs(VS0),
    copy_term(VS0, Copy),
    hook_example(hook_a3, long, 0.5, left,
                 [behind(hook_a3, cube1), hook_down(hook_a3), centred_on(hook_a3, cube1)], E),
    vs_update(VS0, pos(E), _),
    assertion(VS0 =@= Copy).

%   The space converges once every literal of h_s has been shown necessary.
test(converges) :-
    vs_init((tp(h1, c, t) :- hook(h1), behind(h1, c)), VS0),
    assertion(\+ vs_converged(VS0)),
    vs_update(VS0, neg((tp(h2, c, t) :- hook(h2), in_front(h2, c))), VS1),
    assertion(\+ vs_converged(VS1)),
    vs_update(VS1, neg((tp(s1, c, t) :- stick(s1), behind(s1, c))), VS),
    assertion(vs_converged(VS)),
    vs_unknown(VS, U),
    assertion(U == []).

test(covers_bounds) :-
    demo_vs(VS),
    hook_example(hook_b2, long, 0.6, left, [in_front(hook_b2, cube1)], E),
    assertion(vs_covers(VS, hg, E)),
    assertion(\+ vs_covers(VS, hs, E)).

test(bad_bound, [error(domain_error(oneof([hs, hg]), both))]) :-
    demo_vs(VS),
    demo(E),
    vs_covers(VS, both, E).

test(bad_label, [error(domain_error(labelled_example, maybe(p)))]) :-
    demo_vs(VS),
    vs_update(VS, maybe(p), _).

test(non_ground_example, [error(instantiation_error)]) :-
    vs_init((tp(_, c, t) :- hook(c)), _).

test(repeated_head_atom, [error(domain_error(distinct_head_atoms, tp(a, a, t)))]) :-
    vs_init((tp(a, a, t) :- hook(a)), _).


                 /*******************************
                 *   COUNTING THE HYPOTHESES    *
                 *******************************/

%   Small version spaces counted by hand. A hypothesis keeps a subset of h_s's
%   literals and must keep, for every negative, a literal the negative violates.
small_(VS) :-
    vs_init((tp(h1, c, t) :- hook(h1), long(h1), right(h1), behind(h1, c)), VS).

small_neg_(Lits, E) :-
    clause_head_body(E, tp(n, c, t), Lits).

%   No negative yet: every subset of the 4 literals.
test(count_after_the_demonstration) :-
    small_(VS),
    vs_count(VS, N, Exact),
    assertion(N-Exact == 16-true).

%   A failure that violates long/1 and behind/2: every subset but the 4 that keep
%   neither, 16 - 4 = 12.
test(count_after_a_failure_of_two_literals) :-
    small_(VS0),
    small_neg_([hook(n), short(n), right(n), in_front(n, c)], E),
    vs_update(VS0, neg(E), VS),
    vs_space(VS, _, Lits, Cs),
    assertion(length(Lits, 4)),
    assertion(Cs == [[2, 4]]),
    vs_count(VS, N, true),
    assertion(N == 12).

%   Two failures {long, behind} and {behind, right}: behind kept, 2^3 = 8; behind
%   left out, long and right kept, 2 (hook free): 10.
test(count_with_overlapping_failures) :-
    small_(VS0),
    small_neg_([hook(n), short(n), right(n), in_front(n, c)], E1),
    small_neg_([hook(n), long(n), left(n), in_front(n, c)], E2),
    foldl(add_neg_, [E1, E2], VS0, VS),
    vs_count(VS, N, true),
    assertion(N == 10).

%   A failure of behind/2 alone makes it necessary: the superset {long, behind} of
%   an earlier failure says nothing more, 2^3 = 8 (h_g plus any subset of the other
%   three).
test(count_drops_non_minimal_constraints) :-
    small_(VS0),
    small_neg_([hook(n), short(n), right(n), in_front(n, c)], E1),
    small_neg_([hook(n), long(n), right(n), in_front(n, c)], E2),
    foldl(add_neg_, [E1, E2], VS0, VS),
    vs_space(VS, _, _, Cs),
    assertion(Cs == [[4]]),
    vs_count(VS, N, true),
    assertion(N == 8).

%   A success without right/1 removes it from h_s: 2^3 = 8.
test(count_after_a_success) :-
    small_(VS0),
    vs_update(VS0, pos((tp(h2, c, t) :- hook(h2), long(h2), left(h2), behind(h2, c))), VS),
    vs_count(VS, N, true),
    assertion(N == 8).

%   A noisy negative (covered by h_s) constrains nothing.
test(count_ignores_a_noisy_negative) :-
    small_(VS0),
    vs_update(VS0, neg((tp(h1, c, t) :- hook(h1), long(h1), right(h1), behind(h1, c))),
              VS),
    vs_count(VS, N, true),
    assertion(N == 16).

%   The counts and prior masses of vs_space_count/5: hypotheses over {a, b, c} that
%   keep a or b: 6; of those without a: 2 (b kept, c free). With priors 1/2, 1/4,
%   1/3 the mass of "a or b kept" is 1 - 1/2 * 3/4 = 5/8, "a left out, b kept"
%   1/2 * 1/4 = 1/8.
test(space_count_and_mass) :-
    vs_space_count([a, b, c], [[1, 2]], [], [], N-_),
    assertion(N == 6),
    vs_space_count([a, b, c], [[1, 2]], [1], [], NOut-_),
    assertion(NOut == 2),
    vs_space_count([a, b, c], [[1, 2]], [], [1r2, 1r4, 1r3], N1-M),
    assertion(N1-M == 6-5r8),
    vs_space_count([a, b, c], [[1, 2]], [1], [1r2, 1r4, 1r3], N2-M2),
    assertion(N2-M2 == 2-1r8),
    vs_space_count([a, b, c], [[1, 2]], [1, 2], [1r2, 1r4, 1r3], N3-M3),
    assertion(N3-M3 == 0-0).

%   More than 20 literals in the negatives' violation sets: an upper bound, said so.
%   One failure violating 21 of 22 literals: 2^22 - 2^1.
test(count_beyond_twenty_literals_is_a_bound) :-
    numlist(1, 22, Is),
    maplist(lit_(h1), Is, Ls),
    clause_head_body(E, tp(h1, c, t), Ls),
    vs_init(E, VS0),
    maplist(lit_(n), Is, [L1|_]),
    clause_head_body(N, tp(n, c, t), [L1]),
    vs_update(VS0, neg(N), VS),
    vs_count(VS, Count, Exact),
    assertion(Exact == false),
    assertion(Count =:= 2^22 - 2).

lit_(O, I, p(O, I)).

%   vs_count/3 against a brute-force count: every subset of h_s's body that,
%   as the body of a clause with h_s's head, covers none of the negatives.
%   Two disjoint failure sets ({1,2} and {3,4} of six literals: 3 * 3 * 4 = 36),
%   two overlapping ones ({1,2} and {2,3}: 5 * 8 = 40), and 30 seeded random
%   sets of one to four failures.
test(count_with_disjoint_failures_is_brute_force) :-
    bf_count_([[1, 2], [3, 4]], N, BF),
    assertion(N == 36),
    assertion(BF == 36).

test(count_with_overlapping_failures_is_brute_force) :-
    bf_count_([[1, 2], [2, 3]], N, BF),
    assertion(N == 40),
    assertion(BF == 40).

test(count_is_brute_force_on_random_failures) :-
    forall(between(1, 30, Seed),
           ( set_random(seed(Seed)),
             random_between(1, 4, NF),
             length(Fs, NF),
             maplist(random_failure_, Fs),
             bf_count_(Fs, N, BF),
             assertion(N == BF) )).

random_failure_(F) :-
    findall(I, ( between(1, 6, I), random_between(0, 2, 0) ), F0),
    (   F0 == []
    ->  random_between(1, 6, I),
        F = [I]
    ;   F = F0
    ).

%   bf_count_(+Failures, -Count, -BruteForce): a version space over six unary
%   literals updated with one negative per failure set (the literals at those
%   positions replaced), its vs_count/3, and the brute-force count.
bf_count_(Failures, Count, BF) :-
    numlist(1, 6, Is),
    maplist(bf_lit_(h1), Is, Ls),
    clause_head_body(E, tp(h1, c, t), Ls),
    vs_init(E, VS0),
    maplist(bf_negative_(Is), Failures, Negs),
    foldl(add_neg_, Negs, VS0, VS),
    vs_count(VS, Count, Exact),
    assertion(Exact == true),
    vs_bounds(VS, HS, _),
    clause_head_body(HS, Head, Body),
    findall(S, bf_subset_(Body, S), Subsets),
    include(bf_consistent_(Head, Negs), Subsets, Consistent),
    length(Consistent, BF).

bf_lit_(O, I, L) :-
    atom_concat(p, I, P),
    L =.. [P, O].

bf_negative_(Is, Failed, E) :-
    maplist(bf_neg_lit_(Failed), Is, Ls),
    clause_head_body(E, tp(n, c, t), Ls).

bf_neg_lit_(Failed, I, L) :-
    (   memberchk(I, Failed)
    ->  atom_concat(q, I, P)
    ;   atom_concat(p, I, P)
    ),
    L =.. [P, n].

bf_subset_([], []).
bf_subset_([L|Ls], S) :-
    bf_subset_(Ls, S0),
    (   S = [L|S0]
    ;   S = S0
    ).

bf_consistent_(Head, Negs, Body) :-
    clause_head_body(H, Head, Body),
    \+ ( member(N, Negs), clause_covers(H, N) ).

add_neg_(E, VS0, VS) :-
    vs_update(VS0, neg(E), VS).

:- end_tests(version_space).
