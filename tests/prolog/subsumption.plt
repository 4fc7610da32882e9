:- begin_tests(subsumption).

test(atom_instance) :-
    theta_subsumes(p(_, _), p(a, b)).

test(atom_repeated_variable, [fail]) :-
    theta_subsumes(p(X, X), p(a, b)).

test(more_literals_in_specific) :-
    theta_subsumes((p(X) :- q(X, _)), (p(a) :- q(a, b), r(b))).

test(missing_literal, [fail]) :-
    theta_subsumes((p(X) :- q(X, Y), r(Y)), (p(a) :- q(a, b), r(c))).

test(chain_needs_backtracking) :-
    theta_subsumes((p(X) :- q(X, Y), r(Y)), (p(a) :- q(a, c), q(a, b), r(b))).

%   Nienhuys-Cheng & de Wolf (1997), ch. 9 (after Gottlob 1987): the
%   self-recursive clause C implies D = C resolved with itself, but C does
%   not theta-subsume D, so theta-subsumption is weaker than implication.
test(implication_without_subsumption, [fail]) :-
    theta_subsumes((p(f(X)) :- p(X)), (p(f(f(Y))) :- p(Y))).

%   ... while D does not subsume C either.
test(implication_converse, [fail]) :-
    theta_subsumes((p(f(f(Y))) :- p(Y)), (p(f(X)) :- p(X))).

%   A clause subsumes its own factor: p(X,Y) :- q(X,Y), q(Y,X) subsumes
%   p(a,a) :- q(a,a) (both literals map onto one).
test(literals_may_merge) :-
    theta_subsumes((p(X, Y) :- q(X, Y), q(Y, X)), (p(a, a) :- q(a, a))).

test(specific_variables_are_constants, [fail]) :-
    theta_subsumes((p(a) :- q(a)), (p(_) :- q(_))).

test(variant_clauses) :-
    theta_subsumes((p(X) :- q(X, _)), (p(Y) :- q(Y, W), r(W))).

test(negated_literals_by_sign, [fail]) :-
    theta_subsumes((p(X) :- \+ q(X)), (p(a) :- q(a))).

test(negated_literals_match) :-
    theta_subsumes((p(X) :- \+ q(X)), (p(a) :- \+ q(a), r(a))).

% Range tests

test(range_number_inside) :-
    theta_subsumes((p(X) :- len(X, L), in_range(L, 0.25, 0.45)), (p(a) :- len(a, 0.3))).

test(range_number_outside, [fail]) :-
    theta_subsumes((p(X) :- len(X, L), in_range(L, 0.25, 0.45)), (p(a) :- len(a, 0.5))).

test(range_backtracks_to_other_literal) :-
    theta_subsumes((p(X) :- len(X, L), in_range(L, 0.25, 0.45)),
                   (p(a) :- len(a, 0.6), len(a, 0.3))).

test(range_specific_range_within) :-
    theta_subsumes((p(X) :- len(X, L), in_range(L, 0.2, 0.5)),
                   (p(A) :- len(A, V), in_range(V, 0.3, 0.4))).

test(range_specific_range_wider, [fail]) :-
    theta_subsumes((p(X) :- len(X, L), in_range(L, 0.2, 0.5)),
                   (p(A) :- len(A, V), in_range(V, 0.1, 0.4))).

test(range_specific_unranged_variable, [fail]) :-
    theta_subsumes((p(X) :- len(X, L), in_range(L, 0.2, 0.5)), (p(A) :- len(A, _))).

test(range_on_head_argument) :-
    theta_subsumes((p(X) :- in_range(X, 0, 1)), p(0.5)).

test(range_on_unbound_variable) :-
    theta_subsumes((p(_) :- in_range(_, 0, 1)), p(a)).

test(malformed_range, [error(type_error(number, a))]) :-
    theta_subsumes((p(X) :- in_range(X, a, 1)), p(0.5)).

% The bound

%   Mapping the complete graph K5 into K4 is impossible (5 colours needed)
%   and takes a search (the vertices are body variables, not fixed by the
%   head; tens of thousands of inferences); with a tiny limit it must raise,
%   never fail.
test(inference_limit_raises, [error(resource_error(inference_limit(2000)))]) :-
    k5_into_k4(G, S),
    theta_subsumes(G, S, [inference_limit(2000)]).

test(inference_limit_enough, [fail]) :-
    k5_into_k4(G, S),
    theta_subsumes(G, S).

%   A 200-literal chain of shared variables with repeated predicates: the
%   most-constrained-first order finds the identity mapping at once.
test(large_clause_subsumes_itself) :-
    length(Vs, 201),
    numlist(1, 200, Ns),
    maplist(chain_literal_(Vs), Ns, Lits),
    Vs = [V1|_],
    clause_head_body(C, p(V1), Lits),
    copy_term(C, C1),
    theta_subsumes(C1, C).

chain_literal_(Vs, N, L) :-
    nth1(N, Vs, X),
    N1 is N + 1,
    nth1(N1, Vs, Y),
    K is N mod 5,
    (   K =:= 0
    ->  L = len(X, N)
    ;   K =:= 1
    ->  L = link(X, Y)
    ;   L = rel(K, X, Y)
    ).

k5_into_k4(G, S) :-
    length(Vs, 5),
    findall(I-J, ( between(1, 5, I), between(1, 5, J), I =\= J ), Edges),
    maplist(edge_(Vs), Edges, GLits),
    clause_head_body(G, g, GLits),
    findall(e(X, Y), ( between(1, 4, X), between(1, 4, Y), X =\= Y ), SLits),
    clause_head_body(S, g, SLits).

edge_(Vs, I-J, e(X, Y)) :-
    nth1(I, Vs, X),
    nth1(J, Vs, Y).

% Reduction

%   Plotkin (1970): p(X) :- q(X,Y), q(X,a) reduces to p(X) :- q(X,a).
test(plotkin_reduction, [true(R =@= (p(X) :- q(X, a)))]) :-
    clause_reduce((p(X) :- q(X, _), q(X, a)), R).

test(reduction_chain, [true(R =@= (p(X) :- q(X, W), q(W, V), r(V)))]) :-
    clause_reduce((p(X) :- q(X, Y), q(Y, _), q(X, W), q(W, V), r(V)), R).

test(reduction_keeps_reduced, [true(R =@= (p(X) :- q(X, Y), r(Y)))]) :-
    clause_reduce((p(X) :- q(X, Y), r(Y)), R).

test(reduction_duplicates, [true(R =@= (p(X) :- q(X), r(X)))]) :-
    clause_reduce((p(X) :- q(X), r(X), q(X)), R).

test(reduction_unit, [true(R == p(a))]) :-
    clause_reduce(p(a), R).

%   A literal whose variable is ranged more tightly subsumes the looser one.
test(reduction_with_ranges,
     [true(R =@= (p(X) :- len(X, V), in_range(V, 0, 1)))]) :-
    clause_reduce((p(X) :- len(X, V), len(X, W), in_range(V, 0, 1), in_range(W, 0, 2)), R).

test(reduction_ranges_not_merged,
     [true(R =@= (p(X) :- len(X, V), len(X, W), in_range(V, 0, 1), in_range(W, 0.5, 2)))]) :-
    clause_reduce((p(X) :- len(X, V), len(X, W), in_range(V, 0, 1), in_range(W, 0.5, 2)), R).

%   A duplicated chain of three: removing any literal of the first copy
%   needs all of Y, Z, W to move together, so the local test (only the
%   literal's own variables move) fails and the exact test is needed.
test(reduction_needs_exact_test,
     [true(R =@= (p(X) :- q(X, A), r(A, B), s(B, _)))]) :-
    clause_reduce((p(X) :- q(X, Y), r(Y, Z), s(Z, _), q(X, A), r(A, B), s(B, _)), R).

test(reduction_without_exact_test_keeps_literals,
     [true(R =@= (p(X) :- q(X, Y), r(Y, Z), s(Z, W), q(X, A), r(A, B), s(B, C)))]) :-
    clause_reduce((p(X) :- q(X, Y), r(Y, Z), s(Z, W), q(X, A), r(A, B), s(B, C)), R,
                  [full_test_max(0)]).

test(reduction_limit_error, [error(resource_error(inference_limit(1)))]) :-
    clause_reduce((p(X) :- q(X, Y), r(Y, Z), s(Z, _), q(X, A), r(A, B), s(B, _)), _,
                  [test_limit(1), on_limit(error)]).

test(reduction_not_a_clause, [error(type_error(clause, 1))]) :-
    clause_reduce(1, _).

% Coverage and violated literals

test(covers) :-
    clause_covers((tool_pose(T, C, _) :- behind(T, C)),
                  (tool_pose(h1, c1, t1) :- behind(h1, c1), hook(h1))).

test(covers_atom_example, [fail]) :-
    clause_covers((tool_pose(T, _, _) :- hook(T)), tool_pose(h1, c1, t1)).

test(violations_one, [true(V =@= [behind(T, C)])]) :-
    Clause = (tool_pose(T, C, _) :- hook(T), behind(T, C)),
    clause_violations(Clause, (tool_pose(h1, c1, t1) :- hook(h1), in_front(h1, c1)), V).

test(violations_are_clause_terms, [true(V == [behind(T, C)])]) :-
    Clause = (tool_pose(T, C, _) :- hook(T), behind(T, C)),
    clause_violations(Clause, (tool_pose(h1, c1, t1) :- hook(h1)), V).

test(violations_none, [true(V == [])]) :-
    clause_violations((tool_pose(T, C, _) :- behind(T, C)),
                      (tool_pose(h1, c1, t1) :- behind(h1, c1)), V).

test(violations_head_mismatch, [fail]) :-
    clause_violations((tool_pose(T, T, _) :- hook(T)), (tool_pose(h1, c1, t1) :- hook(h1)), _).

test(violations_in_body_order, [true(V =@= [a(X), c(X)])]) :-
    clause_violations((p(X) :- a(X), b(X), c(X), d(X)), (p(k) :- b(k), d(k)), V).

%   The best substitution: Y = b satisfies q and r, only s(Y) is violated.
test(violations_maximal, [true(V =@= [s(_)])]) :-
    clause_violations((p(X) :- q(X, Y), r(Y), s(Y), t(Y)),
                      (p(a) :- q(a, c), s(c), q(a, b), r(b), t(b)), V).

test(violations_range, [true(V =@= [in_range(_, 0.25, 0.45)])]) :-
    clause_violations((p(X) :- len(X, L), in_range(L, 0.25, 0.45)), (p(a) :- len(a, 0.6)), V).

:- end_tests(subsumption).
