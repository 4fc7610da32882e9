:- begin_tests(nbr).

test(one_literal_suffices, [true(R =@= (p(X) :- b(X)))]) :-
    nbr_reduce((p(X) :- a(X), b(X), c(X)), [(p(n1) :- a(n1), c(n1))], R).

%   Muggleton & Feng (1990), negative-based reduction: the first prefix
%   a, b excludes both negatives; b moves to the front; then a is still
%   needed (b alone covers n2), so the result is a, b and c, d are dropped.
test(two_negatives, [true(R =@= (p(X) :- a(X), b(X)))]) :-
    nbr_reduce((p(X) :- a(X), b(X), c(X), d(X)),
               [ (p(n1) :- a(n1), c(n1), d(n1)),
                 (p(n2) :- b(n2), c(n2)) ], R).

test(no_negatives_empty_body, [true(R =@= p(_))]) :-
    nbr_reduce((p(X) :- a(X), b(X)), [], R).

test(atom_negative_needs_one_literal, [true(R =@= (p(X) :- a(X)))]) :-
    nbr_reduce((p(X) :- a(X), b(X)), [p(n1)], R).

test(result_covers_no_negative) :-
    Negs = [ (tp(h1, c, t) :- hook(h1), short(h1), in_front(h1, c)),
             (tp(h2, c, t) :- stick(h2), long(h2), behind(h2, c)),
             (tp(h3, c, t) :- hook(h3), long(h3), in_front(h3, c)) ],
    nbr_reduce((tp(T, C, _) :- hook(T), long(T), behind(T, C)), Negs, R),
    assertion(\+ ( member(N, Negs), clause_covers(R, N) )),
    assertion(R =@= (tp(T1, C1, _) :- hook(T1), behind(T1, C1))).

test(range_kept_with_its_literal,
     [true(R =@= (p(X) :- len(X, L), in_range(L, 0.3, 0.5)))]) :-
    nbr_reduce((p(X) :- a(X), len(X, L), in_range(L, 0.3, 0.5)),
               [(p(n) :- a(n), len(n, 0.9))], R).

%   A literal left out takes the range test on its variable with it.
test(range_dropped_with_its_literal, [true(R =@= (p(X) :- a(X)))]) :-
    nbr_reduce((p(X) :- a(X), len(X, L), in_range(L, 0.3, 0.5)),
               [(p(n1) :- len(n1, 0.4))], R).

test(covering_clause_is_an_error,
     [error(domain_error(clause_covering_no_negative, (p(_) :- a(_))))]) :-
    nbr_reduce((p(X) :- a(X)), [(p(n1) :- a(n1), b(n1))], _).

test(bad_negative, [error(type_error(clause, 7))]) :-
    nbr_reduce((p(X) :- a(X)), [7], _).

:- end_tests(nbr).
