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

:- end_tests(version_space).
