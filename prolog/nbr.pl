:- module(nbr,
          [ nbr_reduce/3             % +Clause, +Negatives, -Reduced
          ]).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(subsumption, [clause_head_body/3, clause_covers/2]).

/** <module> Negative-based reduction (Golem)

Golem's negative-based reduction (Muggleton & Feng 1990) shortens the body
of a clause that covers no negative example while keeping it consistent.

A negative example is a ground clause `Head :- Facts` (the facts true in
that example) or an atom with no facts; a clause covers it in the sense of
subsumption:clause_covers/2 (theta-subsumption, range tests included).

Algorithm, with Fixed = [] and Rest = the body:

  1. Find the shortest prefix P of Rest such that `Head :- Fixed, P` covers
     no negative (coverage only shrinks as literals are added, so a binary
     search over the prefix length is exact).
  2. If P is empty, the result is `Head :- Fixed`.
  3. Otherwise the last literal of P is moved to Fixed (Golem moves it to the
     front of the clause), Rest becomes P without that literal (the literals
     after P are not needed), and step 1 repeats.

The result body lists the chosen literals in their original body order. Range
tests (`in_range/3`) are literals like the others; a range test left without
any literal binding its variable is removed (it would hold for any value).
*/

%!  nbr_reduce(+Clause, +Negatives:list, -Reduced) is det.
%
%   Reduced is Clause with its body reduced by negative-based reduction
%   against Negatives (see the module comment): Reduced covers no negative
%   and no literal of it was found removable by the algorithm. Raises
%   domain_error(clause_covering_no_negative, Clause) when Clause itself
%   covers one of Negatives, and type_error(clause, X) for a malformed
%   clause or negative.
%
%   ==
%   ?- nbr_reduce((p(X) :- a(X), b(X), c(X)), [(p(n1) :- a(n1), c(n1))], R).
%   R = (p(X) :- b(X)).
%   ==
nbr_reduce(Clause, Negatives, Reduced) :-
    clause_head_body(Clause, Head, Body),
    must_be(list, Negatives),
    maplist(check_negative_, Negatives),
    (   member(Neg, Negatives),
        clause_covers(Clause, Neg)
    ->  domain_error(clause_covering_no_negative, Clause)
    ;   true
    ),
    number_body_(Body, 1, Items),
    nbr_(Head, [], Items, Negatives, Chosen),
    keysort(Chosen, Sorted),
    items_lits_(Sorted, Lits0),
    drop_unbound_tests_(Head, Lits0, Lits),
    clause_head_body(Reduced, Head, Lits).

check_negative_(Neg) :-
    clause_head_body(Neg, _, _).

number_body_([], _, []).
number_body_([L|Ls], I, [I-L|Items]) :-
    I1 is I + 1,
    number_body_(Ls, I1, Items).

nbr_(Head, Fixed, Rest, Negatives0, Chosen) :-
    include(covered_by_(Head, Fixed, []), Negatives0, Negatives),
    (   Negatives == []
    ->  Chosen = Fixed
    ;   length(Rest, N),
        shortest_prefix_(Head, Fixed, Rest, Negatives, 1, N, K),
        length(Prefix, K),
        append(Prefix, _, Rest),
        split_last_(Prefix, Before, Last),
        nbr_(Head, [Last|Fixed], Before, Negatives, Chosen)
    ).

%   shortest_prefix_(+Head, +Fixed, +Rest, +Negs, +Lo, +Hi, -K): the least K
%   in Lo..Hi such that Fixed plus the first K of Rest covers no negative;
%   the full prefix (K = Hi) is known to be consistent.
shortest_prefix_(Head, Fixed, Rest, Negs, Lo, Hi, K) :-
    (   Lo >= Hi
    ->  K = Hi
    ;   Mid is (Lo + Hi) // 2,
        length(Prefix, Mid),
        append(Prefix, _, Rest),
        (   member(Neg, Negs),
            covered_by_(Head, Fixed, Prefix, Neg)
        ->  Lo1 is Mid + 1,
            shortest_prefix_(Head, Fixed, Rest, Negs, Lo1, Hi, K)
        ;   shortest_prefix_(Head, Fixed, Rest, Negs, Lo, Mid, K)
        )
    ).

covered_by_(Head, Fixed, Prefix, Neg) :-
    append(Fixed, Prefix, Items),
    items_lits_(Items, Lits),
    clause_head_body(C, Head, Lits),
    clause_covers(C, Neg),
    !.

split_last_([X|Xs], Before, Last) :-
    split_last_(Xs, X, Before, Last).

split_last_([], X, [], X).
split_last_([Y|Ys], X, [X|Before], Last) :-
    split_last_(Ys, Y, Before, Last).

items_lits_([], []).
items_lits_([_-L|Items], [L|Lits]) :-
    items_lits_(Items, Lits).

drop_unbound_tests_(Head, Lits, Kept) :-
    exclude(range_test_, Lits, Others),
    term_variables(Head-Others, Live),
    exclude(unbound_test_(Live), Lits, Kept).

range_test_(in_range(_, _, _)).

unbound_test_(Live, in_range(V, _, _)) :-
    var(V),
    \+ ( member(W, Live), W == V ).
