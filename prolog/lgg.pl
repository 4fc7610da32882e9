:- module(lgg,
          [ term_lgg/3,              % +T1, +T2, -G
            clause_lgg/3,            % +C1, +C2, -G
            in_range/3               % ?X, +Lo, +Hi
          ]).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(assoc)).
:- use_module(library(pairs)).
:- use_module(library(ordsets)).
:- use_module(library(clpr), [{}/1]).
:- use_module(subsumption, [clause_head_body/3, clause_reduce/2]).

/** <module> Least general generalisation of terms and clauses

Plotkin's least general generalisation (LGG, anti-unification), extended to
numbers (the *constrained LGG*).

*Terms.* term_lgg/3 is plain Plotkin: the same pair of differing subterms is
replaced by the same variable everywhere; numbers are constants like atoms.
Variables of the inputs are subterms: a variable generalises to itself only
against the identical variable.

*Clauses.* clause_lgg/3 pairs the heads (same name and arity required) and
every body literal of the first clause with every body literal of the second
clause that has the same predicate symbol, arity and sign (`\+ L` pairs only
with `\+ L2`), using ONE substitution table for the whole clause. The result
keeps only *head-connected* literals (a literal is kept when it shares a
variable with the head, or with a kept literal, transitively; ground literals
are kept too: they are facts both examples share) and is then reduced with
clause_reduce/2. Body order: the order of the first clause's literals, each
followed by its pairings in the second clause's order; range literals last.

*Intervals.* A numeric interval is the body literal `in_range(V, Lo, Hi)`:
V lies in the closed interval [Lo,Hi], Lo =< Hi, Lo and Hi the smallest and
largest value seen (integers and floats kept as given). In clause_lgg/3 two
different numbers N1, N2 generalise to a variable V plus
`in_range(V, min(N1,N2), max(N1,N2))`; a variable that carries
`in_range(V, L, H)` in one clause, paired with a number or with another ranged
variable in the other clause, generalises to a variable with the hull
interval. A ranged variable paired with a non-number (or an unranged
variable) generalises to a plain variable. The same pair always gives the
same variable, as in Plotkin's LGG. in_range/3 is also an executable CLP(R)
constraint (see below), so a learned clause can be run or solved.
*/

%!  in_range(?X, +Lo, +Hi) is semidet.
%
%   X lies in the closed interval [Lo,Hi]. For a number X this is a test;
%   for a variable it posts the CLP(R) constraints `{X >= Lo, X =< Hi}`.
%   An empty interval (Lo > Hi) holds for no X. Raises type_error(number, X)
%   for any other X.
%
%   ==
%   ?- in_range(0.3, 0.25, 0.45).
%   true.
%   ?- in_range(X, 0.25, 0.45), {X >= 0.4}, inf(X, I).
%   I = 0.4.
%   ==
in_range(X, Lo, Hi) :-
    must_be(number, Lo),
    must_be(number, Hi),
    (   number(X)
    ->  Lo =< X,
        X =< Hi
    ;   var(X)
    ->  { X >= Lo, X =< Hi }
    ;   type_error(number, X)
    ).

%!  term_lgg(+T1, +T2, -G) is det.
%
%   G is the least general generalisation (Plotkin anti-unification) of T1
%   and T2: the same pair of differing subterms maps to the same variable.
%
%   ==
%   ?- term_lgg(f(a, g(a)), f(b, g(b)), G).
%   G = f(X, g(X)).
%   ==
term_lgg(T1, T2, G) :-
    term_variables(T1-T2, Vars),
    copy_term_nat(Vars-(T1-T2), CVars-(K1-K2)),
    numbervars(CVars, 0, _, [functor_name('$lgg_sk')]),
    empty_assoc(Tab0),
    empty_assoc(NoRanges),
    Ctx = ctx(plain, NoRanges, NoRanges),
    lgg_(K1, K2, G0, Ctx, s(Tab0, []), _),
    unskolemise_(G0, Vars, G).

%!  clause_lgg(+C1, +C2, -G) is det.
%
%   G is the reduced, head-connected, constrained LGG of the clauses C1 and
%   C2 (see the module comment). Raises type_error(clause, C) when C1 or C2
%   is not a clause and domain_error(clause_head(Name/Arity), H2) when the
%   head H2 of C2 does not have the name and arity of C1's head.
%
%   ==
%   ?- clause_lgg((daughter(mary, ann) :- female(mary), parent(ann, mary)),
%                 (daughter(eve, tom) :- female(eve), parent(tom, eve)), G).
%   G = (daughter(A, B) :- female(A), parent(B, A)).
%   ?- clause_lgg((p(a) :- len(a, 0.3)), (p(b) :- len(b, 0.5)), G).
%   G = (p(A) :- len(A, L), in_range(L, 0.3, 0.5)).
%   ==
clause_lgg(C1, C2, G) :-
    clause_head_body(C1, H1, B1),
    clause_head_body(C2, H2, B2),
    functor(H1, N, A),
    (   functor(H2, N, A)
    ->  true
    ;   domain_error(clause_head(N/A), H2)
    ),
    term_variables(C1-C2, Vars),
    copy_term_nat(Vars-(H1-B1-H2-B2), CVars-(K1-L1-K2-L2)),
    numbervars(CVars, 0, _, [functor_name('$lgg_sk')]),
    split_ranges_(L1, Lits1, R1),
    split_ranges_(L2, Lits2, R2),
    empty_assoc(Tab0),
    Ctx = ctx(constrained, R1, R2),
    lgg_(K1, K2, GH, Ctx, s(Tab0, []), S1),
    body_index_(Lits2, Index2),
    foldl(pair_literal_(Ctx, Index2), Lits1, GLits0, S1, s(_, Ranges)),
    append(GLits0, GLits1),
    list_to_set(GLits1, GLits),
    reverse(Ranges, RangesInOrder),
    maplist(range_literal_, RangesInOrder, RangeLits),
    unskolemise_(GH-GLits-RangeLits, Vars, UH-ULits-URanges),
    head_connected_(UH, ULits, Connected),
    term_variables(UH-Connected, Live),
    include(ranged_var_in_(Live), URanges, LiveRanges),
    append(Connected, LiveRanges, Body),
    clause_head_body(Raw, UH, Body),
    clause_reduce(Raw, G).

%   Anti-unification core. Ctx = ctx(Mode, Ranges1, Ranges2) with Mode plain
%   or constrained and RangesI an assoc from skolemised ranged variables of
%   clause I to Lo-Hi. State s(Table, Ranges): Table maps T1-T2 to its
%   variable, Ranges lists V-Lo-Hi (newest first).
lgg_(T1, T2, G, Ctx, S0, S) :-
    (   T1 == T2
    ->  G = T1,
        same_term_range_(T1, Ctx, S0, S)
    ;   compound(T1),
        compound(T2),
        \+ skolem_(T1),
        \+ skolem_(T2),
        compound_name_arity(T1, Name, Arity),
        compound_name_arity(T2, Name, Arity)
    ->  compound_name_arguments(T1, Name, Args1),
        compound_name_arguments(T2, Name, Args2),
        foldl(lgg_arg_(Ctx), Args1, Args2, Args, S0, S),
        compound_name_arguments(G, Name, Args)
    ;   S0 = s(Tab0, Ranges0),
        (   get_assoc(T1-T2, Tab0, V)
        ->  G = V,
            S = S0
        ;   put_assoc(T1-T2, Tab0, G, Tab),
            (   pair_interval_(T1, T2, Ctx, Lo, Hi)
            ->  S = s(Tab, [G-Lo-Hi|Ranges0])
            ;   S = s(Tab, Ranges0)
            )
        )
    ).

lgg_arg_(Ctx, A1, A2, G, S0, S) :-
    lgg_(A1, A2, G, Ctx, S0, S).

skolem_('$lgg_sk'(_)).

%   An identical ranged variable keeps a range only if it has one in both
%   clauses (the hull); it is recorded once.
same_term_range_(T, ctx(Mode, R1, R2), S0, S) :-
    (   Mode == constrained,
        skolem_(T),
        get_assoc(T, R1, L1-H1),
        get_assoc(T, R2, L2-H2),
        S0 = s(Tab, Ranges0),
        \+ ( member(V-_-_, Ranges0), V == T )
    ->  Lo is min(L1, L2),
        Hi is max(H1, H2),
        S = s(Tab, [T-Lo-Hi|Ranges0])
    ;   S = S0
    ).

pair_interval_(T1, T2, ctx(constrained, R1, R2), Lo, Hi) :-
    value_interval_(T1, R1, L1, H1),
    value_interval_(T2, R2, L2, H2),
    Lo is min(L1, L2),
    Hi is max(H1, H2).

value_interval_(T, Ranges, Lo, Hi) :-
    (   number(T)
    ->  Lo = T,
        Hi = T
    ;   skolem_(T),
        get_assoc(T, Ranges, Lo-Hi)
    ).

%   Range literals leave the body and become an assoc Skolem -> Lo-Hi (the
%   hull when a variable has several).
split_ranges_(Lits, Others, Ranges) :-
    partition(range_lit_, Lits, RangeLits, Others),
    empty_assoc(R0),
    foldl(add_range_, RangeLits, R0, Ranges).

range_lit_(in_range(_, _, _)).

range_literal_(V-Lo-Hi, in_range(V, Lo, Hi)).

add_range_(in_range(V, Lo, Hi), R0, R) :-
    must_be(number, Lo),
    must_be(number, Hi),
    (   skolem_(V)
    ->  (   get_assoc(V, R0, L0-H0)
        ->  L is max(L0, Lo),
            H is min(H0, Hi)
        ;   L = Lo,
            H = Hi
        ),
        put_assoc(V, R0, L-H, R)
    ;   R = R0
    ).

body_index_(Lits, Index) :-
    map_list_to_pairs(lit_key_, Lits, Keyed),
    keysort(Keyed, Sorted),
    group_pairs_by_key(Sorted, Groups),
    list_to_assoc(Groups, Index).

lit_key_(L, Key) :-
    (   L = (\+ A)
    ->  functor(A, N, Ar),
        Key = neg(N/Ar)
    ;   functor(L, N, Ar),
        Key = pos(N/Ar)
    ).

pair_literal_(Ctx, Index2, L1, GLits, S0, S) :-
    lit_key_(L1, Key),
    (   get_assoc(Key, Index2, Partners)
    ->  foldl(lgg_lit_(Ctx, L1), Partners, GLits, S0, S)
    ;   GLits = [],
        S = S0
    ).

lgg_lit_(Ctx, L1, L2, G, S0, S) :-
    lgg_(L1, L2, G, Ctx, S0, S).

unskolemise_(T0, Vars, T) :-
    (   var(T0)
    ->  T = T0
    ;   T0 = '$lgg_sk'(I)
    ->  nth0(I, Vars, T)
    ;   compound(T0)
    ->  compound_name_arguments(T0, Name, Args0),
        maplist(unskolemise_arg_(Vars), Args0, Args),
        compound_name_arguments(T, Name, Args)
    ;   T = T0
    ).

unskolemise_arg_(Vars, A0, A) :-
    unskolemise_(A0, Vars, A).

ranged_var_in_(Live, in_range(V, _, _)) :-
    member(W, Live),
    W == V,
    !.

%   head_connected_(+Head, +Lits, -Kept): keep ground literals and literals
%   linked to the head's variables through shared variables. A search from
%   the head's variables over an index variable -> literals, so each literal
%   and each variable is visited once (linear in the size of the body,
%   whatever the order of a chain of literals).
head_connected_(Head, Lits, Kept) :-
    copy_term_nat(Head-Lits, CHead-CLits),
    numbervars(CHead-CLits, 0, _, [functor_name('$hc')]),
    var_ids_(CHead, HeadIds),
    length(Lits, N),
    numlist_(1, N, Ps),
    maplist(var_ids_, CLits, LitIds),
    compound_name_arguments(IdTerm, ids, LitIds),
    findall(V-P, ( nth1(P, LitIds, Ids), member(V, Ids) ), Occ0),
    keysort(Occ0, Occ1),
    group_pairs_by_key(Occ1, Occ2),
    list_to_assoc(Occ2, Occ),
    empty_assoc(Seen0),
    foldl(seen_var_, HeadIds, Seen0, Seen1),
    reach_(HeadIds, Occ, IdTerm, Seen1, _, [], Reached0),
    sort(Reached0, Reached1),
    pairs_keys_values(ReachedPairs, Reached1, Reached1),
    list_to_assoc(ReachedPairs, Reached),
    pairs_keys_values(Positioned, Ps, Lits),
    pairs_keys_values(IdLits, LitIds, Positioned),
    include(connected_lit_(Reached), IdLits, KeptPairs),
    pairs_values(KeptPairs, KeptPos),
    pairs_values(KeptPos, Kept).

var_ids_(T, Ids) :-
    findall(N, sub_term('$hc'(N), T), Ns),
    sort(Ns, Ids).

numlist_(I, N, Ps) :-
    (   I > N
    ->  Ps = []
    ;   Ps = [I|Ps1],
        I1 is I + 1,
        numlist_(I1, N, Ps1)
    ).

seen_var_(V, S0, S) :-
    put_assoc(V, S0, true, S).

%   reach_(+Queue, +Occ, +IdTerm, +Seen0, -Seen, +Acc0, -Acc): Acc are the
%   positions of the literals reached from the variables in Queue (IdTerm's
%   argument P: the variables of literal P).
reach_([], _, _, Seen, Seen, Acc, Acc).
reach_([V|Vs], Occ, IdTerm, Seen0, Seen, Acc0, Acc) :-
    (   get_assoc(V, Occ, Ps)
    ->  foldl(reach_lit_(IdTerm), Ps, Vs-Seen0-Acc0, Queue-Seen1-Acc1)
    ;   Queue = Vs,
        Seen1 = Seen0,
        Acc1 = Acc0
    ),
    reach_(Queue, Occ, IdTerm, Seen1, Seen, Acc1, Acc).

reach_lit_(IdTerm, P, Q0-S0-A0, Q-S-[P|A0]) :-
    arg(P, IdTerm, Ids),
    foldl(new_var_, Ids, Q0-S0, Q-S).

new_var_(V, Q0-S0, Q-S) :-
    (   get_assoc(V, S0, _)
    ->  Q = Q0,
        S = S0
    ;   put_assoc(V, S0, true, S),
        Q = [V|Q0]
    ).

connected_lit_(Reached, Ids-(P-_)) :-
    (   Ids == []
    ->  true
    ;   get_assoc(P, Reached, _)
    ).
