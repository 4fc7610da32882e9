%   The faster clause_lgg/3 and clause_reduce/2 (issue 18) against the
%   algorithms they replaced, kept in reference/lgg_reference.pl: equal results
%   up to variable renaming on seeded random clause pairs.

:- use_module(reference/lgg_reference).

:- begin_tests(lgg_equivalence).

%   300 seeded pairs of relational examples (2 to 24 body literals, shared and
%   private objects, numbers, negations, ranges on variables in the first).
test(clause_lgg_equals_reference_on_random_pairs) :-
    forall(between(1, 300, Seed),
           ( eq_pair_(Seed, C1, C2),
             clause_lgg(C1, C2, G),
             ref_clause_lgg(C1, C2, R),
             assertion(G =@= R) )).

%   400 seeded clauses with variables (chains, duplicates up to renaming,
%   range tests): the same Plotkin reduction as the reference.
test(clause_reduce_equals_reference_on_random_clauses) :-
    forall(between(1, 400, Seed),
           ( eq_clause_(Seed, C),
             clause_reduce(C, G),
             ref_clause_reduce(C, R),
             assertion(G =@= R) )).

%   The unreduced LGG of two larger examples (40 literals each, a giant
%   component): the same reduction with unbounded tests.
test(clause_reduce_equals_reference_on_a_large_lgg) :-
    eq_scene_(7, 40, E1),
    eq_scene_(8, 40, E2),
    ref_lgg_unreduced(E1, E2, Raw),
    clause_reduce(Raw, G, [test_limit(infinite)]),
    ref_clause_reduce(Raw, R, [test_limit(infinite)]),
    assertion(G =@= R).

%   Head connection is transitive: every kept literal with variables reaches
%   the head through kept literals, and no dropped literal shares a variable
%   with a kept one or with the head.
test(head_connection_is_closed_on_random_pairs) :-
    forall(between(1, 100, Seed),
           ( eq_pair_(Seed, C1, C2),
             clause_lgg(C1, C2, G),
             clause_head_body(G, H, B),
             term_variables(H, HV),
             eq_reach_(HV, B, Reached),
             forall(( member(L, B), \+ ground(L), L \= in_range(_, _, _) ),
                    assertion(( member(R, Reached), R == L ))) )).

:- end_tests(lgg_equivalence).

eq_reach_(Vs0, Lits, Reached) :-
    partition(eq_touches_(Vs0), Lits, In, Out),
    (   In == []
    ->  Reached = []
    ;   term_variables(Vs0-In, Vs1),
        eq_reach_(Vs1, Out, Reached1),
        append(In, Reached1, Reached)
    ).

eq_touches_(Vs, L) :-
    term_variables(L, LVs),
    member(V, LVs),
    member(W, Vs),
    V == W,
    !.

eq_pair_(Seed, C1, C2) :-
    set_random(seed(Seed)),
    random_between(2, 24, N1),
    random_between(2, 24, N2),
    random_between(2, 6, K),
    eq_body_(N1, K, a, B1),
    eq_body_(N2, K, b, B2),
    (   Seed mod 3 =:= 0
    ->  B1a = [len(a0, W), in_range(W, 0.1, 0.4)|B1]
    ;   B1a = B1
    ),
    clause_head_body(C1, t(a0, c), B1a),
    clause_head_body(C2, t(b0, c), B2).

eq_body_(N, K, Prefix, Body) :-
    length(Body, N),
    maplist(eq_literal_(K, Prefix), Body).

eq_literal_(K, Prefix, L) :-
    random_between(0, 7, Kind),
    eq_object_(K, Prefix, A),
    eq_object_(K, Prefix, B),
    (   Kind =:= 0
    ->  random_member(V, [hook, stick]),
        L = kind(A, V)
    ;   Kind =:= 1
    ->  random_between(1, 9, C),
        X is C / 10,
        L = len(A, X)
    ;   Kind =:= 2
    ->  L = on(A, B)
    ;   Kind =:= 3
    ->  L = left_of(A, B)
    ;   Kind =:= 4
    ->  L = (\+ broken(A))
    ;   Kind =:= 5
    ->  L = near(A, B, c)
    ;   Kind =:= 6
    ->  L = wide(A)
    ;   L = door_open(c)
    ).

eq_object_(K, Prefix, O) :-
    random_between(0, K, I),
    (   I =:= K
    ->  O = c
    ;   atom_concat(Prefix, I, O)
    ).

eq_clause_(Seed, C) :-
    set_random(seed(Seed)),
    random_between(1, 10, N),
    Vars = [X, Y, _, _, _, _],
    length(Body0, N),
    maplist(eq_var_literal_(Vars), Body0),
    (   Seed mod 4 =:= 0
    ->  random_member(Vr, Vars),
        random_between(0, 5, Lo),
        Hi is Lo + 3,
        Body = [len(Vr, Vr2), in_range(Vr2, Lo, Hi)|Body0]
    ;   Body = Body0
    ),
    clause_head_body(C, p(X, Y), Body).

eq_var_literal_(Vars, L) :-
    random_between(0, 4, Kind),
    random_member(A, Vars),
    random_member(B, Vars),
    (   Kind =:= 0
    ->  L = q(A, B)
    ;   Kind =:= 1
    ->  L = r(A)
    ;   Kind =:= 2
    ->  L = q(A, k)
    ;   Kind =:= 3
    ->  L = s(A, B, A)
    ;   L = (\+ t(A))
    ).

eq_scene_(Seed, N, E) :-
    set_random(seed(Seed)),
    eq_body_(N, 8, o, B),
    clause_head_body(E, t(o0, c), B).
