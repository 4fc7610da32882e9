:- module(rlgg,
          [ rlgg/4,                  % +E1, +E2, +BK, -Clause
            rlgg/5,                  % +E1, +E2, +BK, -Clause, +Options
            saturate/4               % +Example, +BK, -Clause, +Options
          ]).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(assoc)).
:- use_module(library(option)).
:- use_module(library(pairs)).
:- use_module(library(ordsets)).
:- use_module(lgg, [clause_lgg/3]).
:- use_module(subsumption, [clause_head_body/3]).

/** <module> Relative least general generalisation (Golem)

Golem's RLGG (Muggleton & Feng 1990): each positive example is saturated
with the ground background facts linked to it, giving a ground clause
`Example :- Facts`; the RLGG is the clause_lgg/3 of the two saturated
clauses, which keeps the head-connected literals and reduces the result.
Finally, ground body literals that are facts of BK are dropped: the clause is
read relative to BK, where they always hold (they come from facts shared by
both saturations, e.g. `parent(ann, tom)`).

*Saturation (ij-determinacy style).* The example's constants form level 0.
A background fact joins the saturation at level k when it mentions a
constant of level k-1 or lower; its constants then belong to level k. With
depth(I) the facts of levels 1..I are kept, i.e. the facts reachable from the
head's constants in at most I steps. Only atoms link facts (numbers are
measured values, and linking through them would join unrelated objects that
happen to share a value); pass link_numbers(true) to link through numbers
too. A fact equal to the example itself is left out. Facts keep the order of
BK.
*/

%!  rlgg(+E1, +E2, +BK:list, -Clause) is det.
%!  rlgg(+E1, +E2, +BK:list, -Clause, +Options) is det.
%
%   Clause is the relative LGG of the ground positive examples E1 and E2
%   with respect to the ground facts BK. Options:
%
%     - depth(+I)
%       Saturation depth, default 2.
%     - link_numbers(+Bool)
%       Let numbers link facts, default false.
%
%   ==
%   ?- BK = [parent(ann, mary), parent(ann, tom), parent(tom, eve),
%            parent(tom, ian), female(ann), female(mary), female(eve)],
%      rlgg(daughter(mary, ann), daughter(eve, tom), BK, C).
%   C = (daughter(A, B) :- parent(B, A), female(A)).
%   ==
rlgg(E1, E2, BK, Clause) :-
    rlgg(E1, E2, BK, Clause, []).

rlgg(E1, E2, BK, Clause, Options) :-
    saturate(E1, BK, C1, Options),
    saturate(E2, BK, C2, Options),
    clause_lgg(C1, C2, G),
    clause_head_body(G, Head, Body0),
    exclude(background_fact_(BK), Body0, Body),
    clause_head_body(Clause, Head, Body).

background_fact_(BK, L) :-
    ground(L),
    memberchk(L, BK).

%!  saturate(+Example, +BK:list, -Clause, +Options) is det.
%
%   Clause is `Example :- Facts`, Facts the facts of BK linked to Example
%   within the saturation depth (see the module comment; options as for
%   rlgg/5). Raises an instantiation error when Example or a fact is not
%   ground and type_error(callable, X) for a non-callable one.
%
%   ==
%   ?- saturate(d(a), [p(a, b), q(b, c), r(z)], C, [depth(1)]).
%   C = (d(a) :- p(a, b)).
%   ==
saturate(Example, BK, Clause, Options) :-
    must_be(callable, Example),
    must_be(ground, Example),
    must_be(list, BK),
    maplist(must_be(callable), BK),
    maplist(must_be(ground), BK),
    must_be(list, Options),
    option(depth(Depth), Options, 2),
    must_be(nonneg, Depth),
    option(link_numbers(Numbers), Options, false),
    must_be(boolean, Numbers),
    number_facts_(BK, 1, Numbered),
    constant_index_(Numbered, Numbers, Index),
    list_to_assoc(Numbered, ByPosition),
    term_constants_(Example, Numbers, Level0),
    empty_assoc(Taken0),
    expand_(Depth, Level0, Level0, ctx(Index, ByPosition, Numbers), Taken0, Taken),
    assoc_to_keys(Taken, Positions),
    findall(F, ( member(P, Positions), get_assoc(P, ByPosition, F), F \== Example ), Facts),
    clause_head_body(Clause, Example, Facts).

number_facts_([], _, []).
number_facts_([F|Fs], I, [I-F|Ns]) :-
    I1 is I + 1,
    number_facts_(Fs, I1, Ns).

constant_index_(Numbered, Numbers, Index) :-
    findall(C-I, ( member(I-F, Numbered), term_constants_(F, Numbers, Cs), member(C, Cs) ), Pairs0),
    keysort(Pairs0, Pairs),
    group_pairs_by_key(Pairs, Groups),
    list_to_assoc(Groups, Index).

%   The linking constants of a term: atoms in argument positions (and
%   numbers when asked), not functor names.
term_constants_(T, Numbers, Cs) :-
    T =.. [_|Args],
    findall(C, ( member(A, Args), sub_term(C, A), linking_constant_(C, Numbers) ), Cs0),
    sort(Cs0, Cs).

linking_constant_(C, Numbers) :-
    (   atom(C)
    ->  true
    ;   Numbers == true,
        number(C)
    ).

expand_(Depth, Frontier, Known0, Ctx, Taken0, Taken) :-
    Ctx = ctx(Index, ByPosition, Numbers),
    (   Depth =:= 0
    ->  Taken = Taken0
    ;   Frontier == []
    ->  Taken = Taken0
    ;   findall(P, ( member(C, Frontier), get_assoc(C, Index, Ps), member(P, Ps) ), New0),
        sort(New0, New1),
        exclude(taken_(Taken0), New1, New),
        foldl(take_, New, Taken0, Taken1),
        findall(C, ( member(P, New), get_assoc(P, ByPosition, F),
                     term_constants_(F, Numbers, FCs), member(C, FCs) ), Cs0),
        sort(Cs0, Cs),
        ord_subtract(Cs, Known0, Frontier1),
        ord_union(Known0, Frontier1, Known1),
        Depth1 is Depth - 1,
        expand_(Depth1, Frontier1, Known1, Ctx, Taken1, Taken)
    ).

taken_(Taken, P) :-
    get_assoc(P, Taken, _).

take_(P, T0, T) :-
    put_assoc(P, T0, true, T).
