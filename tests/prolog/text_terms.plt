:- begin_tests(text_terms).

deep_(0, a) :- !.
deep_(N, f(T)) :- N1 is N - 1, deep_(N1, T).

test(reads_every_clause_as_data) :-
    text_terms("a(1). b :- c. :- halt.", Ts),
    Ts == [a(1), (b :- c), (:- halt)].

test(a_directive_is_never_called) :-
    tmp_file(ran, Flag),
    format(string(Text), ":- initialization(shell('touch ~w')).~n:- shell('touch ~w').~n",
           [Flag, Flag]),
    text_terms(Text, [_, _]),
    \+ exists_file(Flag).

test(a_term_as_deep_as_the_limit_is_read) :-
    term_depth_max(Max),
    deep_(Max, T),
    must_be_shallow(T).

test(a_term_deeper_than_the_limit_is_refused,
     [throws(error(representation_error(term_depth(200)), _))]) :-
    term_depth_max(Max),
    Deeper is Max + 1,
    deep_(Deeper, T),
    must_be_shallow(T).

test(operators_nest_without_brackets,
     [throws(error(representation_error(term_depth(200)), _))]) :-
    length(Ms, 1000),
    maplist(=("- "), Ms),
    atomic_list_concat(Ms, Prefix),
    atom_concat(Prefix, 'a.', Text),
    text_terms(Text, _).

test(long_lists_and_clause_bodies_are_not_nesting) :-
    numlist(1, 100000, L),
    must_be_shallow(L),
    length(Gs, 10000),
    maplist(=(g), Gs),
    atomic_list_concat(Gs, ',', Body),
    term_to_atom(B, Body),
    must_be_shallow((h :- B)).

test(one_term_and_nothing_after_it) :-
    text_term("f(X, Y)", T, Bindings),
    T = f(A, B), Bindings == ['X'=A, 'Y'=B].

test(text_after_the_term_is_refused, [throws(error(syntax_error(one_term_expected), _))]) :-
    text_term("a. b", _, _).

:- end_tests(text_terms).
