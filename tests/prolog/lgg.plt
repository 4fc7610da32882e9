:- begin_tests(lgg).

%   Plotkin (1970), "A note on inductive generalization": the same pair of
%   differing subterms is replaced by the same variable.
test(plotkin_shared_pair, [true(G =@= f(X, g(X)))]) :-
    term_lgg(f(a, g(a)), f(b, g(b)), G).

%   Nienhuys-Cheng & de Wolf (1997), Foundations of ILP, ch. 13:
%   lgg([a,b,a], [c,d,c]) = [X,Y,X].
test(list_pairs, [true(G =@= [X, _, X])]) :-
    term_lgg([a, b, a], [c, d, c], G).

test(different_pairs_different_variables, [true(G =@= f(X, Y, X, Y))]) :-
    term_lgg(f(a, b, a, b), f(b, a, b, a), G).

test(identical_variable_stays, [true(G == f(X, g(X)))]) :-
    term_lgg(f(X, g(X)), f(X, g(X)), G).

test(variable_vs_other_variable, [true((G = f(V, W), var(V), V \== X, V \== Y, W == Z))]) :-
    term_lgg(f(X, Z), f(Y, Z), G).

test(numbers_are_constants_in_terms, [true(G =@= f(_, 3))]) :-
    term_lgg(f(1, 3), f(2, 3), G).

test(different_functors, [true(G =@= h(_, a))]) :-
    term_lgg(h(f(a), a), h(g(a), a), G).

%   Lavrac & Dzeroski (1994), Inductive Logic Programming, section 2.2
%   (the daughter example of Muggleton & Feng 1990).
test(daughter_clauses,
     [true(G =@= (daughter(X, Y) :- female(X), parent(Y, X)))]) :-
    clause_lgg((daughter(mary, ann) :- female(mary), parent(ann, mary)),
               (daughter(eve, tom) :- female(eve), parent(tom, eve)), G).

%   Literals pair across the whole body with one table; q(V2, V3) from the
%   cross pair is not connected to the head and is dropped.
test(cross_pairs_and_head_connection, [true(G =@= (p(X) :- q(X, _)))]) :-
    clause_lgg((p(a) :- q(a, b), q(b, c)), (p(d) :- q(d, e)), G).

%   Head connection through a chain of body literals written in the reverse
%   order of the chain (r3 reaches the head only through r2, r1 and r0): the
%   whole chain is kept, the unconnected z/2 is dropped.
test(head_connected_through_a_reversed_chain,
     [true(G =@= (p(A) :- r3(D, _), r2(C, D), r1(B, C), r0(A, B)))]) :-
    clause_lgg((p(a) :- r3(d, e), r2(c, d), r1(b, c), r0(a, b), z(u, v)),
               (p(a2) :- r3(d2, e2), r2(c2, d2), r1(b2, c2), r0(a2, b2), z(u2, v2)), G).

%   A chain that reaches the head only through a literal paired across the
%   two bodies in a different order; the ground literal is kept on its own.
test(head_connected_through_a_shuffled_chain,
     [true(G =@= (p(A) :- s(C, _), door(d1), q(B, C), q(A, B)))]) :-
    clause_lgg((p(a) :- s(c, x), door(d1), q(b, c), q(a, b)),
               (p(e) :- q(e, f), door(d1), s(g, y), q(f, g)), G).

test(negated_literals_pair_by_sign,
     [true(G =@= (p(X) :- q(X), \+ r(X)))]) :-
    clause_lgg((p(a) :- q(a), \+ r(a), s(b)), (p(c) :- q(c), r(c), \+ r(c)), G).

test(unit_clauses, [true(G =@= p(_, b))]) :-
    clause_lgg(p(a, b), p(c, b), G).

test(ground_shared_literal_kept, [true(G =@= (p(X) :- q(X), door_open(door1)))]) :-
    clause_lgg((p(a) :- q(a), door_open(door1)), (p(b) :- q(b), door_open(door1)), G).

test(result_is_reduced, [true(G =@= (p(X) :- q(X, a)))]) :-
    clause_lgg((p(b) :- q(b, a), q(b, c)), (p(d) :- q(d, a), q(d, e)), G).

% Constrained LGG

test(numbers_become_range,
     [true(G =@= (p(X) :- len(X, L), in_range(L, 0.3, 0.5)))]) :-
    clause_lgg((p(a) :- len(a, 0.5)), (p(b) :- len(b, 0.3)), G).

test(same_number_pair_same_variable,
     [true(G =@= (p(X) :- s(X, V, V), in_range(V, 1, 2)))]) :-
    clause_lgg((p(a) :- s(a, 1, 1)), (p(b) :- s(b, 2, 2)), G).

test(equal_numbers_stay, [true(G =@= (p(X) :- len(X, 0.4)))]) :-
    clause_lgg((p(a) :- len(a, 0.4)), (p(b) :- len(b, 0.4)), G).

test(ranged_variable_and_number_hull,
     [true(G =@= (p(X) :- len(X, L), in_range(L, 0.3, 0.7)))]) :-
    clause_lgg((p(A) :- len(A, V), in_range(V, 0.3, 0.5)), (p(b) :- len(b, 0.7)), G).

test(two_ranged_variables_hull,
     [true(G =@= (p(X) :- len(X, L), in_range(L, 0.1, 0.9)))]) :-
    clause_lgg((p(A) :- len(A, V), in_range(V, 0.3, 0.5)),
               (p(B) :- len(B, W), in_range(W, 0.1, 0.9)), G).

test(ranged_variable_and_atom_plain,
     [true(G =@= (p(X) :- len(X, _)))]) :-
    clause_lgg((p(A) :- len(A, V), in_range(V, 0.3, 0.5)), (p(b) :- len(b, long)), G).

test(integer_and_float_range, [true(G =@= (p(X) :- n(X, V), in_range(V, 1, 2.5)))]) :-
    clause_lgg((p(a) :- n(a, 1)), (p(b) :- n(b, 2.5)), G).

%   The law a property test will also check: the LGG subsumes both inputs.
test(lgg_subsumes_both_inputs) :-
    C1 = (tool_pose(hook_a2, cube1, tube1) :-
              hook(hook_a2), handle_length(hook_a2, medium),
              handle_length_m(hook_a2, 0.35), behind(hook_a2, cube1)),
    C2 = (tool_pose(hook_b1, cube1, tube1) :-
              hook(hook_b1), handle_length(hook_b1, long),
              handle_length_m(hook_b1, 0.55), in_front(hook_b1, cube1)),
    clause_lgg(C1, C2, G),
    assertion(theta_subsumes(G, C1)),
    assertion(theta_subsumes(G, C2)),
    assertion(G =@= (tool_pose(T, cube1, tube1) :- hook(T), handle_length(T, _),
                     handle_length_m(T, L), in_range(L, 0.35, 0.55))).

% in_range/3 as a CLP(R) constraint

test(in_range_number) :-
    in_range(0.3, 0.25, 0.45).

test(in_range_number_outside, [fail]) :-
    in_range(0.5, 0.25, 0.45).

test(in_range_posts_constraint, [true(Inf =:= 0.25)]) :-
    in_range(X, 0.25, 0.45),
    clpr:inf(X, Inf).

test(in_range_constraint_rejects, [fail]) :-
    in_range(X, 0.25, 0.45),
    X = 0.5.

test(in_range_atom, [error(type_error(number, long))]) :-
    in_range(long, 0.25, 0.45).

% Errors

test(number_is_not_a_clause, [error(type_error(clause, 3))]) :-
    clause_lgg(3, p(a), _).

test(variable_head, [error(type_error(clause, (_ :- q)))]) :-
    clause_lgg((_ :- q), p(a), _).

test(number_in_body, [error(type_error(clause, (p :- q, 1)))]) :-
    clause_lgg((p :- q, 1), p, _).

test(different_heads, [error(domain_error(clause_head(p/1), q(a)))]) :-
    clause_lgg(p(a), q(a), _).

%   Laws on 40 seeded random pairs of relational examples with numbers:
%   the LGG subsumes both inputs, and it is reduced (reducing it again
%   changes nothing).
test(laws_on_random_pairs) :-
    forall(between(1, 40, Seed),
           ( random_example_(Seed, E1),
             Seed2 is Seed + 1000,
             random_example_(Seed2, E2),
             clause_lgg(E1, E2, G),
             assertion(theta_subsumes(G, E1)),
             assertion(theta_subsumes(G, E2)),
             clause_reduce(G, R),
             assertion(R =@= G) )).

random_example_(Seed, E) :-
    set_random(seed(Seed)),
    random_between(2, 8, N),
    length(Lits, N),
    maplist(random_literal_, Lits),
    clause_head_body(E, t(o0, o1), Lits).

random_literal_(L) :-
    random_between(0, 3, K),
    random_member(A, [o0, o1, o2, o3]),
    random_member(B, [o0, o1, o2, o3]),
    (   K =:= 0
    ->  random_member(V, [short, long]),
        L = size(A, V)
    ;   K =:= 1
    ->  random_between(1, 9, C),
        X is C / 10,
        L = len(A, X)
    ;   K =:= 2
    ->  L = on(A, B)
    ;   L = (\+ broken(A))
    ).

:- end_tests(lgg).
