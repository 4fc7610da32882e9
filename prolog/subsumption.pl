:- module(subsumption,
          [ theta_subsumes/2,        % +General, +Specific
            theta_subsumes/3,        % +General, +Specific, +Options
            clause_reduce/2,         % +Clause, -Reduced
            clause_reduce/3,         % +Clause, -Reduced, +Options
            clause_covers/2,         % +Clause, +Example
            clause_violations/3,     % +Clause, +Example, -Violated
            clause_violations/4,     % +Clause, +Example, -Violated, +Options
            clause_head_body/3       % ?Clause, ?Head, ?Body
          ]).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(assoc)).
:- use_module(library(option)).
:- use_module(library(pairs)).
:- use_module(library(heaps)).
:- use_module(library(ordsets)).

/** <module> Theta-subsumption, Plotkin reduction and coverage of clauses

Clauses are written `Head :- Body` with a conjunction body; a unit clause is
just `Head`. A body literal is an atom or a negated atom `\+ Atom`; `\+ p(X)`
is matched only against `\+ p(...)` literals (literals are paired by predicate
symbol and sign).

*Range tests.* A body literal `in_range(V, Lo, Hi)` (see lgg:in_range/3) is a
*test*, not a literal to match: it is satisfied when V is bound to a number in
the closed interval [Lo,Hi], or to a variable of the specific clause whose own
`in_range(V2, Lo2, Hi2)` literal lies within [Lo,Hi], or when V stays unbound
(V occurs in no other literal, so some value in the interval exists).

*Search.* The specific clause is skolemised (its variables become constants).
The general clause's head is unified with the specific head first, so the head
variables are fixed; the body then splits into *components*: sets of literals
linked by variables that are not in the head. Components share no variables
and are matched independently. Each component is searched with forward
checking and dynamic ordering: at every node the candidate literals of each
open literal are cut to those that still unify, an empty set fails the node,
literals that became ground are settled without branching, and the search
branches on the literal with the fewest candidates left. A range test runs as
soon as its variable is bound.

*Bound.* Every search runs under call_with_inference_limit/3. The default
limit is 10,000,000 inferences (about one second); set it with the option
inference_limit(N) (N an integer or `infinite`). When the limit is hit the
predicate raises `error(resource_error(inference_limit(N)), _)`: it never
fails silently on a hard instance.
*/

% ---------------------------------------------------------------------------
% Clause syntax

%!  clause_head_body(?Clause, ?Head, ?Body:list) is det.
%
%   Relate a clause `Head :- Conjunction` (or the unit clause `Head`) to its
%   head and the list of its body literals. With Clause bound, parse it and
%   raise type_error(clause, Clause) when it is not a clause (a variable or
%   a number as head or literal, a non-callable in the body). With Clause
%   unbound, build it from Head and the list Body (`[]` gives the unit clause).
%
%   ==
%   ?- clause_head_body((p(X) :- q(X), \+ r(X)), H, B).
%   H = p(X), B = [q(X), \+ r(X)].
%   ==
clause_head_body(Clause, Head, Body) :-
    (   var(Clause)
    ->  must_be(callable, Head),
        must_be(list, Body),
        (   Body == []
        ->  Clause = Head
        ;   list_conj_(Body, Conj),
            Clause = (Head :- Conj)
        )
    ;   parse_clause_(Clause, Head, Body)
    ).

parse_clause_(Clause, Head, Body) :-
    (   Clause = (H :- B)
    ->  head_ok_(H, Clause),
        conj_list_(B, Clause, Body0),
        Head = H,
        Body = Body0
    ;   head_ok_(Clause, Clause),
        Head = Clause,
        Body = []
    ).

head_ok_(H, Clause) :-
    (   callable(H),
        H \= (_, _),
        H \= (\+ _),
        H \= (_ :- _)
    ->  true
    ;   type_error(clause, Clause)
    ).

conj_list_(B, Clause, Lits) :-
    (   var(B)
    ->  type_error(clause, Clause)
    ;   B == true
    ->  Lits = []
    ;   B = (A, C)
    ->  conj_list_(A, Clause, L1),
        conj_list_(C, Clause, L2),
        append(L1, L2, Lits)
    ;   literal_ok_(B)
    ->  Lits = [B]
    ;   type_error(clause, Clause)
    ).

literal_ok_(L) :-
    callable(L),
    (   L = (\+ A)
    ->  callable(A),
        A \= (\+ _)
    ;   true
    ).

list_conj_([L], L) :-
    !.
list_conj_([L|Ls], (L, C)) :-
    list_conj_(Ls, C).

% ---------------------------------------------------------------------------
% Theta-subsumption

%!  theta_subsumes(+General, +Specific) is semidet.
%!  theta_subsumes(+General, +Specific, +Options) is semidet.
%
%   True when the clause (or atom) General theta-subsumes the clause (or
%   atom) Specific: some substitution maps General's head onto Specific's
%   head and every body literal of General onto a body literal of Specific,
%   and General's range tests hold under it (see the module comment).
%   Specific's variables are treated as constants. Options:
%
%     - inference_limit(+N)
%       Bound on the search, default 10,000,000; raises
%       resource_error(inference_limit(N)) when exceeded.
%
%   ==
%   ?- theta_subsumes((p(X) :- q(X, Y)), (p(a) :- q(a, b), r(b))).
%   true.
%   ?- theta_subsumes((p(X) :- q(X, V), in_range(V, 0, 1)), (p(a) :- q(a, 2))).
%   false.
%   ==
theta_subsumes(General, Specific) :-
    theta_subsumes(General, Specific, []).

theta_subsumes(General, Specific, Options) :-
    must_be(list, Options),
    inference_limit_(Options, Limit),
    clause_head_body(General, GH0, GB0),
    clause_head_body(Specific, SH0, SB0),
    copy_term_nat(GH0-GB0, GH-GB),
    copy_term_nat(SH0-SB0, SH-SB),
    skolemise_(SH-SB),
    split_body_(SB, SLits, STests),
    number_items_(SLits, 1, SItems),
    spec_index_(SItems, Index),
    spec_ranges_(STests, Ranges),
    limited_(Limit, subsumes_body_(GH, GB, SH, Index, Ranges)).

subsumes_body_(GH, GB, SH, Index, Ranges) :-
    GH = SH,
    split_body_(GB, GLits, GTests0),
    number_items_(GLits, 1, GItems),
    number_items_(GTests0, 1, GTests),
    components_(GItems, GTests, Comps),
    empty_assoc(NoExclusion),
    maplist(match_component_(Index, Ranges, NoExclusion), Comps).

match_component_(Index, Ranges, Excl, comp(Items, Tests)) :-
    maplist(candidates_(Index, Excl), Items, Cands),
    dyn_search_(Items, Cands, Tests, Ranges, Excl, _).

%!  clause_covers(+Clause, +Example) is semidet.
%
%   True when Clause covers the example clause Example (`Head :- Facts`, the
%   facts true in the example, or an atom with no facts): Clause
%   theta-subsumes Example, range tests included.
%
%   ==
%   ?- clause_covers((tool_pose(T, C, X) :- behind(T, C)),
%                    (tool_pose(h1, c1, t1) :- behind(h1, c1), hook(h1))).
%   true.
%   ==
clause_covers(Clause, Example) :-
    theta_subsumes(Clause, Example, []).

% ---------------------------------------------------------------------------
% Violated literals

%!  clause_violations(+Clause, +Example, -Violated) is semidet.
%!  clause_violations(+Clause, +Example, -Violated, +Options) is semidet.
%
%   Unify (a copy of) Clause's head with the head of the example clause
%   Example (`Head :- Facts`); fail when that is impossible. Then find a
%   substitution that satisfies as many of Clause's body literals as
%   possible in Example's facts and return, in body order, the literals of
%   Clause (the terms as they appear in Clause, not instantiated) that it
%   leaves unsatisfied. `[]` means that Clause covers Example.
%
%   The search is an exact branch and bound per component (see the module
%   comment), bounded by the option max_nodes(N) (default 20,000 search
%   nodes per component). When the bound is hit the best substitution found
%   so far is used, so Violated may then contain more literals than the
%   optimum; it always names literals that are violated by one concrete
%   substitution. Components without local variables (the usual case for
%   structural literals about the head's objects) are exact and immediate.
%
%   ==
%   ?- clause_violations((tool_pose(T, C, X) :- hook(T), behind(T, C)),
%                        (tool_pose(h1, c1, t1) :- hook(h1), in_front(h1, c1)), V).
%   V = [behind(T, C)].
%   ==
clause_violations(Clause, Example, Violated) :-
    clause_violations(Clause, Example, Violated, []).

clause_violations(Clause, Example, Violated, Options) :-
    must_be(list, Options),
    option(max_nodes(MaxNodes), Options, 20000),
    must_be(positive_integer, MaxNodes),
    clause_head_body(Clause, Head, Body),
    clause_head_body(Example, EH0, EB0),
    copy_term_nat(EH0-EB0, EH-EB),
    skolemise_(EH-EB),
    split_body_(EB, ELits, ETests),
    number_items_(ELits, 1, EItems),
    spec_index_(EItems, Index),
    spec_ranges_(ETests, Ranges),
    number_items_(Body, 1, Items0),
    copy_term_nat(Head-Items0, GH-Items),
    GH = EH,
    partition(is_test_item_, Items, TestItems, LitItems),
    components_(LitItems, TestItems, Comps),
    foldl(component_violations_(Index, Ranges, MaxNodes), Comps, [], ViolIdx0),
    sort(ViolIdx0, ViolIdx),
    pairs_at_(ViolIdx, Items0, Violated).

is_test_item_(_-in_range(_, _, _)).

component_violations_(Index, Ranges, MaxNodes, comp(Items, Tests), V0, V) :-
    empty_assoc(Excl),
    order_steps_all_(Items, Tests, Index, Excl, Steps),
    findall(I, step_index_(Steps, I), All),
    length(All, N),
    State = best(N, All, 0),
    (   bb_(Steps, [], 0, Ranges, MaxNodes, State),
        fail
    ;   true
    ),
    arg(2, State, Best),
    append(Best, V0, V).

step_index_(Steps, I) :-
    member(S, Steps),
    arg(1, S, I).

bb_([], Viol, NV, _, _, State) :-
    arg(1, State, Best),
    NV < Best,
    nb_setarg(1, State, NV),
    nb_setarg(2, State, Viol).
bb_([S|Ss], Viol, NV, Ranges, MaxNodes, State) :-
    arg(1, State, Best),
    NV < Best,
    arg(3, State, Nodes),
    Nodes < MaxNodes,
    Nodes1 is Nodes + 1,
    nb_setarg(3, State, Nodes1),
    bb_step_(S, Ss, Viol, NV, Ranges, MaxNodes, State).

bb_step_(lit(I, L, Cands, _), Ss, Viol, NV, Ranges, MaxNodes, State) :-
    (   member(_-C, Cands),
        L = C,
        bb_(Ss, Viol, NV, Ranges, MaxNodes, State)
    ;   NV1 is NV + 1,
        bb_(Ss, [I|Viol], NV1, Ranges, MaxNodes, State)
    ).
bb_step_(test(I, V, Lo, Hi), Ss, Viol, NV, Ranges, MaxNodes, State) :-
    (   range_test_(V, Lo, Hi, Ranges)
    ->  bb_(Ss, Viol, NV, Ranges, MaxNodes, State)
    ;   NV1 is NV + 1,
        bb_(Ss, [I|Viol], NV1, Ranges, MaxNodes, State)
    ).

pairs_at_([], _, []).
pairs_at_([I|Is], Items, [L|Ls]) :-
    memberchk(I-L, Items),
    pairs_at_(Is, Items, Ls).

% ---------------------------------------------------------------------------
% Plotkin reduction

%!  clause_reduce(+Clause, -Reduced) is det.
%!  clause_reduce(+Clause, -Reduced, +Options) is det.
%
%   Reduced is the Plotkin reduction of Clause: duplicate body literals are
%   removed, then a literal L is removed whenever Clause theta-subsumes
%   Clause without L (the clauses are then equivalent), until no literal can
%   go. The head is kept (head variables map to themselves). Only the
%   component of L (its literals linked by non-head variables) has to be
%   mapped, and a successful mapping removes every literal of the component
%   outside its image at once. Range tests stay for the variables that still
%   occur; body order is kept.
%
%   Each redundancy test is first tried *locally* (only the variables of L
%   move, everything else maps to itself: cheap, and it finds most
%   redundancies), then, when the component has at most full_test_max
%   literals, exactly. Candidates come from an index of the clause's literals
%   by predicate and fixed argument, and a local test is first decided by a
%   join over that index (every variable of the test is one of L's, so each
%   image of L makes the rest ground): the search, whose first solution
%   says which literals go, runs only when the join found one. The test_limit
%   bound applies to that search (as before: a test cut by it keeps its
%   literal). Options:
%
%     - test_limit(+N)
%       Inference bound of one exact test, default 20,000 (or `infinite`).
%     - full_test_max(+K)
%       Largest component (in literals) given the exact test, default 60.
%     - on_limit(+Action)
%       `keep` (default): a test that hits test_limit keeps its literal;
%       `error`: raise resource_error(inference_limit(N)).
%
%   With the defaults the result is always equivalent to Clause, and it is
%   the exact Plotkin reduction whenever no component is larger than
%   full_test_max and no test hit the limit (true of every clause of the
%   hook and wedge cases; the LGG of two 200-literal relational examples is
%   where the bounds start to matter, see bench/engine_bench.pl).
%
%   ==
%   ?- clause_reduce((p(X) :- q(X, Y), q(X, a)), R).
%   R = (p(X) :- q(X, a)).
%   ==
clause_reduce(Clause, Reduced) :-
    clause_reduce(Clause, Reduced, []).

clause_reduce(Clause, Reduced, Options) :-
    must_be(list, Options),
    option(test_limit(TestLimit), Options, 20000),
    (   TestLimit == infinite
    ->  true
    ;   must_be(positive_integer, TestLimit)
    ),
    option(on_limit(OnLimit), Options, keep),
    must_be(oneof([keep, error]), OnLimit),
    option(full_test_max(FullMax), Options, 60),
    must_be(nonneg, FullMax),
    clause_head_body(Clause, Head, Body0),
    list_to_set(Body0, Body),
    split_body_(Body, Lits, Tests),
    number_items_(Lits, 1, Items),
    number_items_(Tests, 1, TestItems),
    reduce_items_(Head, Items, TestItems, TestLimit-FullMax-OnLimit, KeptItems),
    pairs_values(KeptItems, Kept),
    term_variables(Head-Kept, Live),
    include(live_test_(Live), Tests, KeptTests),
    append(Kept, KeptTests, RBody),
    clause_head_body(Reduced, Head, RBody).

live_test_(Live, in_range(V, _, _)) :-
    (   var(V)
    ->  member(W, Live),
        W == V,
        !
    ;   true
    ).

reduce_items_(Head, Items, Tests, TestLimit-FullMax-OnLimit, Kept) :-
    copy_term_nat(Head-Items-Tests, SH-SItems-STests),
    skolemise_(SH-SItems-STests),
    spec_index_(SItems, Index0),
    assoc_to_list(Index0, IndexGroups0),
    maplist(counted_group_, IndexGroups0, IndexGroups),
    hash_index_(IndexGroups, Index),
    arg_index_(SItems, ArgIdx),
    pairs_values(STests, STestLits),
    spec_ranges_(STestLits, Ranges),
    copy_term_nat(Head-Items-Tests, CH-CItems-CTests),
    CH = SH,
    components_(CItems, CTests, Comps),
    list_to_assoc(CItems, CItemAssoc),
    list_to_assoc(Items, ItemAssoc),
    pairs_values(SItems, SLits),
    compound_name_arguments(SAssoc, lits, SLits),
    skolem_occurrences_(SItems, SkOcc),
    skolem_tests_(STests, SkTests),
    skolems_in_(SH, HeadSks),
    empty_assoc(Removed0),
    findall(C-J, member(J-C, SItems), LitJs0),
    keysort(LitJs0, LitJs1),
    group_pairs_by_key(LitJs1, LitJs2),
    pairs_trie_(LitJs2, LitJs),
    Ctx = red(Head, ItemAssoc, Tests, SH, cands(Index, ArgIdx, CItemAssoc, LitJs), Ranges,
              TestLimit-FullMax, OnLimit, local(SAssoc, SkOcc, HeadSks, STests-SkTests)),
    foldl(reduce_component_(Ctx), Comps, Removed0, Removed),
    exclude(removed_item_(Removed), Items, Kept).

removed_item_(Removed, I-_) :-
    get_assoc(I, Removed, _).

%   The literals of a component are tested in body order; Gone (the literals
%   a test removes) always lie in the component, so the number of its live
%   literals is kept as a count rather than recounted for every test.
reduce_component_(Ctx, comp(CItems, _), Removed0, Removed) :-
    pairs_keys(CItems, Idxs),
    (   CItems = [_-L],
        ground(L)
    ->  Removed = Removed0
    ;   length(Idxs, NAlive),
        foldl(reduce_literal_(Ctx, Idxs), Idxs, Removed0-NAlive, Removed-_)
    ).

%   Literal I goes when its component maps into the clause without I (and
%   without the literals removed so far); a literal whose only possible
%   image is itself is skipped at once.
reduce_literal_(Ctx, Idxs, I, Removed0-NAlive0, Removed-NAlive) :-
    Ctx = red(_, _, _, _, CandCtx, _, _, _, _),
    (   get_assoc(I, Removed0, _)
    ->  Removed = Removed0,
        NAlive = NAlive0
    ;   \+ other_image_(CandCtx, I, Removed0)
    ->  Removed = Removed0,
        NAlive = NAlive0
    ;   put_assoc(I, Removed0, true, Excl),
        (   redundant_literal_(Ctx, I, Idxs, NAlive0, Excl, Gone)
        ->  foldl(mark_removed_, Gone, Removed0, Removed),
            length(Gone, NGone),
            NAlive is NAlive0 - NGone
        ;   Removed = Removed0,
            NAlive = NAlive0
        )
    ).

%   other_image_(+CandCtx, +I, +Removed): literal I (head variables bound)
%   unifies with some live literal of the clause other than itself.
other_image_(CandCtx, I, Removed) :-
    CandCtx = cands(_, _, CItemAssoc, _),
    get_assoc(I, CItemAssoc, L),
    source_candidates_(CandCtx, L, Source),
    member(J-C, Source),
    J =\= I,
    \+ get_assoc(J, Removed, _),
    \+ L \= C,
    !.

%   redundant_literal_(+Ctx, +I, +Idxs, +NAlive, +Excl, -Gone): some
%   substitution maps the component Idxs (less the removed literals; NAlive
%   of them are left) into the clause without literal I; Gone are the
%   literals of the component outside its image (I among them). First the
%   local test: every variable except the non-head variables of literal I
%   stays itself, so only the literals that contain those variables are
%   searched (cheap, and it finds most redundancies). Then, for components
%   of at most full_test_max literals, the full test of the component,
%   bounded by test_limit: when the bound is hit the literal is kept (the
%   clause stays equivalent, only perhaps not minimal), unless
%   on_limit(error) was given.
redundant_literal_(Ctx, I, Idxs, NAlive, Excl, Gone) :-
    Ctx = red(Head, ItemAssoc, Tests, SH, CandCtx, Ranges, Limit-FullMax, OnLimit, _),
    (   findall(G, local_gone_(Ctx, I, Excl, G), [Gone0|_])
    ->  Gone = Gone0
    ;   NAlive =< FullMax,
        exclude(removed_key_(Excl), Idxs, Alive0),
        Alive = [I|Alive0],
        maplist(item_at_(ItemAssoc), Alive, KItems0),
        copy_term_nat(Head-KItems0-Tests, GH-KItems-GTests),
        GH = SH,
        term_variables(KItems, KVars),
        include(test_on_(KVars), GTests, KTests),
        maplist(item_cands_(CandCtx), KItems, CandLists),
        bounded_test_(Limit, OnLimit,
                      reduce_match_(KItems, CandLists, KTests, Ranges, Excl, Image)),
        subtract_idx_(Alive, Image, Gone)
    ).

%   The local test's literals are the clause's own (skolemised) literals
%   with only literal I's non-head skolems made variables again; their
%   candidates come from the argument index, so only the literals that
%   agree on a fixed argument are tried.
local_gone_(Ctx, I, Excl, Gone) :-
    Ctx = red(_, _, _, _, CandCtx, Ranges, Limit-_, _,
              local(SAssoc, SkOcc, HeadSks, STests-SkTests)),
    arg(I, SAssoc, SI),
    skolems_in_(SI, Sks0),
    ord_subtract(Sks0, HeadSks, Sks),
    Sks \== [],
    findall(J, ( member(Sk, Sks), get_assoc(Sk, SkOcc, Js), member(J, Js),
                 J =\= I, \+ get_assoc(J, Excl, _) ), Near0),
    sort(Near0, Near1),
    NearIdx = [I|Near1],
    length(Sks, NS),
    length(Vars, NS),
    pairs_keys_values(SkVars, Sks, Vars),
    list_to_assoc(SkVars, Map),
    maplist(general_item_(SAssoc, Map), NearIdx, NearItems),
    findall(T, ( member(Sk, Sks), get_assoc(Sk, SkTests, Ts), member(T, Ts) ), TIdx0),
    sort(TIdx0, TIdx),
    pairs_at_(TIdx, STests, NTests0),
    maplist(unskolem_(Map), NTests0, NTests1),
    local_possible_(CandCtx, Excl, NearItems, NTests1, Ranges),
    maplist(item_cands_(CandCtx), NearItems, CandLists),
    number_items_(NTests1, 1, NTests),
    bounded_test_(Limit, keep,
                  reduce_match_(NearItems, CandLists, NTests, Ranges, Excl, NearImage)),
    subtract_idx_(NearIdx, NearImage, Gone).

%   local_possible_(+CandCtx, +Excl, +NearItems, +Tests, +Ranges): the local
%   test has a solution: an exact check, and a cheap one, of what the search
%   of reduce_match_/6 would find (most literals of a large clause are not
%   redundant, and this rejects them without the search). A join: ground
%   literals only have to be in the clause (a trie lookup); otherwise it
%   branches on the literal with the fewest literals that agree with it on
%   a fixed argument (argument index), which binds its variables.
local_possible_(CandCtx, Excl, NearItems, Tests, Ranges) :-
    pairs_values(NearItems, Lits),
    \+ \+ join_(Lits, CandCtx, Excl, Tests, Ranges).

join_(Lits, CandCtx, Excl, Tests, Ranges) :-
    CandCtx = cands(_, _, _, LitJs),
    partition(ground, Lits, Ground, Open),
    forall(member(L, Ground), present_(LitJs, Excl, L)),
    (   Open == []
    ->  maplist(test_holds_(Ranges), Tests)
    ;   pick_driver_(Open, CandCtx, none, [], L-Source, Rest),
        member(J-C, Source),
        \+ get_assoc(J, Excl, _),
        L = C,
        join_(Rest, CandCtx, Excl, Tests, Ranges)
    ->  true
    ).

%   pick_driver_(+Open, +CandCtx, +Best0, +Skipped, -L-Source, -Rest): the
%   open literal L with the fewest literals agreeing with it on a fixed
%   argument (Source), taken at once when it has at most two; fails when
%   some literal has none.
pick_driver_([], _, N-Best, Skipped, Best, Skipped) :-
    N > 0.
pick_driver_([L|Ls], CandCtx, Best0, Skipped, Best, Rest) :-
    source_candidates_(CandCtx, L, N, Source),
    N > 0,
    (   N =< 2
    ->  Best = L-Source,
        (   Best0 = _-(B0-_)
        ->  Rest = [B0|Rest0]
        ;   Rest = Rest0
        ),
        append(Skipped, Ls, Rest0)
    ;   Best0 = N0-_,
        N0 =< N
    ->  pick_driver_(Ls, CandCtx, Best0, [L|Skipped], Best, Rest)
    ;   (   Best0 = _-(B0-_)
        ->  Skipped1 = [B0|Skipped]
        ;   Skipped1 = Skipped
        ),
        pick_driver_(Ls, CandCtx, N-(L-Source), Skipped1, Best, Rest)
    ).

present_(LitJs, Excl, L) :-
    trie_lookup(LitJs, L, Js),
    member(J, Js),
    \+ get_assoc(J, Excl, _),
    !.

item_cands_(CandCtx, _-L, Cands) :-
    item_candidates_(CandCtx, L, Cands).

%   skolem_tests_(+STests, -SkTests): assoc from a skolem to the positions
%   of the range tests on it.
skolem_tests_(STests, SkTests) :-
    findall(Sk-T, ( member(T-in_range(Sk, _, _), STests), compound(Sk) ), Pairs0),
    keysort(Pairs0, Pairs),
    group_pairs_by_key(Pairs, Groups),
    list_to_assoc(Groups, SkTests).

%   arg_index_(+SItems, -ArgIdx): assoc from Key-Position-Value to the
%   skolemised literals J-C (in the order of J) of predicate Key whose
%   argument Position is the atomic or skolem Value.
arg_index_(SItems, ArgIdx) :-
    findall((Key-P-V)-(J-C), ( member(J-C, SItems), lit_key_(C, Key), lit_atom_(C, A),
                           arg(P, A, V), fixed_arg_(V) ), Pairs0),
    keysort(Pairs0, Pairs),
    group_pairs_by_key(Pairs, Groups0),
    maplist(counted_group_, Groups0, Groups),
    hash_index_(Groups, ArgIdx).

%   hash_index_(+Pairs, -Dict): Pairs (ground keys) as a dict from the keys'
%   term_hash/2 to buckets of pairs, for lookups with hash_lookup_/3 that
%   are faster than an assoc's comparisons of compound keys.
hash_index_(Pairs, Dict) :-
    map_list_to_pairs(pair_hash_, Pairs, Hashed),
    keysort(Hashed, Sorted),
    group_pairs_by_key(Sorted, Buckets),
    dict_pairs(Dict, hidx, Buckets).

pair_hash_(K-_, H) :-
    term_hash(K, H).

hash_lookup_(Dict, K, V) :-
    term_hash(K, H),
    get_dict(H, Dict, Bucket),
    memberchk(K-V, Bucket).

%   pairs_trie_(+Pairs, -Trie): a trie mapping each key of Pairs to its value
%   (a hashed lookup; trie_lookup/3 copies the value, so only for small ones).
pairs_trie_(Pairs, Trie) :-
    trie_new(Trie),
    forall(member(K-V, Pairs), trie_insert(Trie, K, V)).

counted_group_(K-Js, K-(N-Js)) :-
    length(Js, N).

lit_atom_(L, A) :-
    (   L = (\+ A0)
    ->  A = A0
    ;   A = L
    ).

fixed_arg_(V) :-
    (   atomic(V)
    ->  true
    ;   V = '$sk'(N),
        integer(N)
    ).

%   item_candidates_(+CandCtx, +L, -Cands): the J-C of spec_index_ (in its
%   order) of L's predicate that unify with L, the same list as
%   candidates_/4 with no exclusion, found through L's most selective fixed
%   argument when it has one.
item_candidates_(CandCtx, L, Cands) :-
    source_candidates_(CandCtx, L, Source),
    include(unifiable_with_(L), Source, Cands).

%   source_candidates_(+CandCtx, +L, -Source): the J-C of L's predicate (in
%   the order of J) that agree with L on its most selective fixed argument,
%   all of them when L has none.
source_candidates_(CandCtx, L, Source) :-
    source_candidates_(CandCtx, L, _, Source).

%   source_candidates_(+CandCtx, +L, -N, -Source): N is the length of Source.
source_candidates_(cands(Index, ArgIdx, _, _), L, N, Source) :-
    lit_key_(L, Key),
    (   hash_lookup_(Index, Key, NAll-All)
    ->  lit_atom_(L, A),
        functor(A, _, Arity),
        best_arg_(1, Arity, A, Key, ArgIdx, NAll-All, N-Source)
    ;   N = 0,
        Source = []
    ).

best_arg_(P, Arity, A, Key, ArgIdx, Best0, Best) :-
    (   P > Arity
    ->  Best = Best0
    ;   arg(P, A, V),
        (   fixed_arg_(V)
        ->  (   hash_lookup_(ArgIdx, Key-P-V, NJs-Js)
            ->  true
            ;   NJs = 0,
                Js = []
            ),
            Best0 = N0-_,
            (   NJs < N0
            ->  Best1 = NJs-Js
            ;   Best1 = Best0
            )
        ;   Best1 = Best0
        ),
        P1 is P + 1,
        best_arg_(P1, Arity, A, Key, ArgIdx, Best1, Best)
    ).

unifiable_with_(L, _-C) :-
    \+ L \= C.

general_item_(SAssoc, Map, J, J-L) :-
    arg(J, SAssoc, SL),
    unskolem_(Map, SL, L).

unskolem_(Map, T0, T) :-
    (   T0 = '$sk'(_)
    ->  (   get_assoc(T0, Map, V)
        ->  T = V
        ;   T = T0
        )
    ;   compound(T0)
    ->  compound_name_arguments(T0, Name, Args0),
        maplist(unskolem_(Map), Args0, Args),
        compound_name_arguments(T, Name, Args)
    ;   T = T0
    ).

skolems_in_(T, Sks) :-
    findall(Sk, ( sub_term(Sk, T), nonvar(Sk), Sk = '$sk'(_) ), Sks0),
    sort(Sks0, Sks).

skolem_occurrences_(SItems, SkOcc) :-
    findall(Sk-J, ( member(J-SL, SItems), skolems_in_(SL, Sks), member(Sk, Sks) ), Pairs0),
    keysort(Pairs0, Pairs),
    group_pairs_by_key(Pairs, Groups),
    list_to_assoc(Groups, SkOcc).

bounded_test_(Limit, OnLimit, Goal) :-
    (   Limit == infinite
    ->  once(Goal)
    ;   call_with_inference_limit(once(Goal), Limit, Result),
        (   Result == inference_limit_exceeded
        ->  (   OnLimit == error
            ->  resource_error(inference_limit(Limit))
            ;   fail
            )
        ;   true
        )
    ).

removed_key_(Removed, I) :-
    get_assoc(I, Removed, _).

item_at_(ItemAssoc, I, I-L) :-
    get_assoc(I, ItemAssoc, L).

reduce_match_(KItems, CandLists, KTests, Ranges, Excl, Image) :-
    dyn_search_(KItems, CandLists, KTests, Ranges, Excl, Image).

subtract_idx_([], _, []).
subtract_idx_([I|Is], Image, Gone) :-
    (   memberchk(I, Image)
    ->  Gone = Gone1
    ;   Gone = [I|Gone1]
    ),
    subtract_idx_(Is, Image, Gone1).

mark_removed_(I, R0, R) :-
    put_assoc(I, R0, true, R).

% ---------------------------------------------------------------------------
% Shared machinery: skolem constants, index, components, ordering, matching

inference_limit_(Options, Limit) :-
    option(inference_limit(Limit), Options, 10000000),
    (   Limit == infinite
    ->  true
    ;   must_be(positive_integer, Limit)
    ).

limited_(Limit, Goal) :-
    (   Limit == infinite
    ->  once(Goal)
    ;   call_with_inference_limit(once(Goal), Limit, Result),
        (   Result == inference_limit_exceeded
        ->  resource_error(inference_limit(Limit))
        ;   true
        )
    ).

skolemise_(Term) :-
    numbervars(Term, 0, _, [functor_name('$sk'), attvar(bind)]).

split_body_([], [], []).
split_body_([L|Ls], Lits, Tests) :-
    (   L = in_range(_, Lo, Hi)
    ->  must_be(number, Lo),
        must_be(number, Hi),
        Tests = [L|Tests1],
        split_body_(Ls, Lits, Tests1)
    ;   Lits = [L|Lits1],
        split_body_(Ls, Lits1, Tests)
    ).

number_items_([], _, []).
number_items_([L|Ls], I, [I-L|Items]) :-
    I1 is I + 1,
    number_items_(Ls, I1, Items).

lit_key_(L, Key) :-
    (   L = (\+ A)
    ->  functor(A, N, Ar),
        Key = neg(N/Ar)
    ;   functor(L, N, Ar),
        Key = pos(N/Ar)
    ).

spec_index_(Items, Index) :-
    map_list_to_pairs(item_key_, Items, Keyed),
    keysort(Keyed, Sorted),
    group_pairs_by_key(Sorted, Groups),
    list_to_assoc(Groups, Index).

item_key_(_-L, Key) :-
    lit_key_(L, Key).

spec_ranges_(Tests, Ranges) :-
    findall(V-(Lo-Hi), ( member(in_range(V, Lo, Hi), Tests), \+ number(V) ), Pairs0),
    keysort(Pairs0, Pairs),
    group_pairs_by_key(Pairs, Groups),
    list_to_assoc(Groups, Ranges).

range_test_(V, Lo, Hi, Ranges) :-
    (   var(V)
    ->  true
    ;   number(V)
    ->  Lo =< V,
        V =< Hi
    ;   get_assoc(V, Ranges, Rs)
    ->  once(( member(L-H, Rs), L >= Lo, H =< Hi ))
    ;   fail
    ).

%   components_(+Items, +Tests, -Comps): split the literals I-L (head
%   variables already bound) into groups linked by the variables left, as
%   comp(Items, Tests) terms; a range test I-in_range(V, Lo, Hi) joins the
%   group of its variable, and a test on a bound term or on a variable that
%   no literal has forms a group of its own.
components_(Items, Tests, Comps) :-
    copy_term_nat(Items-Tests, CItems-CTests),
    maplist(link_item_vars_, CItems, Keys),
    numbervars(CItems, 0, _, [functor_name('$cv')]),
    pairs_keys_values(Keyed0, Keys, Items),
    keysort(Keyed0, Keyed),
    group_pairs_by_key(Keyed, KeyGroups),
    map_list_to_pairs(first_index_, KeyGroups, ByFirst0),
    keysort(ByFirst0, ByFirst),
    pairs_values(ByFirst, OrderedGroups),
    maplist(test_key_, CTests, TestKeys),
    pairs_keys_values(KeyedTests0, TestKeys, Tests),
    keysort(KeyedTests0, KeyedTests),
    group_pairs_by_key(KeyedTests, TestGroups),
    (   selectchk(lone-Lone, TestGroups, TestGroups1)
    ->  true
    ;   Lone = [],
        TestGroups1 = TestGroups
    ),
    list_to_assoc(TestGroups1, TestAssoc),
    maplist(group_comp_(TestAssoc), OrderedGroups, Comps0),
    maplist(lone_comp_, Lone, LoneComps),
    append(Comps0, LoneComps, Comps).

%   Unifying all variables of each (copied) literal with each other leaves
%   one variable per component, numbered '$cv'(N) afterwards: the literal's
%   key; a ground literal is a component of its own.
link_item_vars_(I-L, Key) :-
    term_variables(L, Vs),
    (   Vs = [V|Vs1]
    ->  maplist(=(V), Vs1),
        Key = V
    ;   Key = ground(I)
    ).

first_index_(_-Group, First) :-
    pairs_keys(Group, Is),
    min_list(Is, First).

%   A test's key: the component of its variable, or lone when the variable
%   is in no literal (still unbound in the copy) or the test is on a bound
%   term.
test_key_(_-in_range(V, _, _), Key) :-
    (   nonvar(V),
        V = '$cv'(_)
    ->  Key = V
    ;   Key = lone
    ).

lone_comp_(T, comp([], [T])).

%   The items of a group in the order of their indices, with the tests on
%   its variables in their order.
group_comp_(TestAssoc, Key-Group, comp(GItems, GTests)) :-
    keysort(Group, GItems),
    (   get_assoc(Key, TestAssoc, GTests)
    ->  true
    ;   GTests = []
    ).

test_on_(Vars, _-in_range(V, _, _)) :-
    var(V),
    member(W, Vars),
    W == V,
    !.

%   order_steps_all_(+Items, +Tests, +Index, +Excl, -Steps): the steps
%   lit(I, L, Cands, J) and test(I, V, Lo, Hi) of one component in a static
%   search order for the branch and bound of clause_violations/4; a literal
%   without candidates is kept (it will be violated).
order_steps_all_(Items, Tests, Index, Excl, Steps) :-
    maplist(candidates_(Index, Excl), Items, Cands),
    weave_(Items, Cands, Tests, Steps).

candidates_(Index, Excl, _-L, Cands) :-
    lit_key_(L, Key),
    (   get_assoc(Key, Index, All)
    ->  include(candidate_ok_(L, Excl), All, Cands)
    ;   Cands = []
    ).

candidate_ok_(L, Excl, J-C) :-
    \+ get_assoc(J, Excl, _),
    \+ L \= C.

%   Greedy static order: repeatedly take the literal with the best score
%   (lower is better): all variables already bound (a pure check) first,
%   then literals sharing a bound variable, then fewest candidates, then
%   most bound variables, then body position. Scores change only for the
%   neighbours of a newly bound variable, so a priority queue with lazy
%   deletion keeps the ordering at O(occurrences * log n). Each test is
%   emitted right after the literal that binds its variable.
weave_(Items, Cands, Tests, Steps) :-
    length(Items, K),
    positions_(1, K, Ps),
    maplist(step_info_, Ps, Items, Cands, Infos),
    copy_term_nat(Items-Tests, CItems-CTests),
    numbervars(CItems-CTests, 0, _, [functor_name('$ov')]),
    maplist(ov_ids_, CItems, LitIds),
    var_occurrences_by_pos_(LitIds, Occ),
    maplist(test_var_, Tests, CTests, Ready0, TestVars),
    exclude(==(none), Ready0, Ready),
    test_index_(TestVars, TestIdx),
    maplist(test_step_, Ready, Steps0),
    list_to_assoc_pos_(Infos, LitIds, State0),
    pairs_keys_values(PosIds0, Ps, LitIds),
    list_to_assoc(PosIds0, PosIds),
    empty_heap(Heap00),
    foldl(push_pos_(State0), Ps, Heap00, Heap0),
    empty_assoc(Bound0),
    order_loop_(Heap0, State0, ctx(Occ, PosIds, TestIdx), Bound0, Steps1, TailTests),
    maplist(test_step_, TailTests, Steps2),
    append([Steps0, Steps1, Steps2], Steps).

positions_(I, K, Ps) :-
    (   I > K
    ->  Ps = []
    ;   Ps = [I|Ps1],
        I1 is I + 1,
        positions_(I1, K, Ps1)
    ).

step_info_(P, I-L, Cands, P-info(I, L, Cands, N)) :-
    length(Cands, N).

ov_ids_(_-L, Ids) :-
    findall(N, sub_term('$ov'(N), L), Ns),
    sort(Ns, Ids).

var_occurrences_by_pos_(LitIds, Occ) :-
    findall(V-P, ( nth1(P, LitIds, Ids), member(V, Ids) ), Pairs0),
    keysort(Pairs0, Pairs),
    group_pairs_by_key(Pairs, Groups),
    list_to_assoc(Groups, Occ).

%   Tests on a bound term are ready at once; others wait for their variable.
test_var_(T, CT, Ready, TV) :-
    CT = _-in_range(V, _, _),
    (   V = '$ov'(N)
    ->  Ready = none,
        TV = N-T
    ;   Ready = T,
        TV = none
    ).

test_index_(TestVars0, TestIdx) :-
    exclude(==(none), TestVars0, TestVars),
    keysort(TestVars, Sorted),
    group_pairs_by_key(Sorted, Groups),
    list_to_assoc(Groups, TestIdx).

test_step_(I-in_range(V, Lo, Hi), test(I, V, Lo, Hi)).

list_to_assoc_pos_(Infos, LitIds, State) :-
    maplist(initial_state_, Infos, LitIds, Pairs),
    list_to_assoc(Pairs, State).

initial_state_(P-Info, Ids, P-st(Info, U, 0, open)) :-
    length(Ids, U).

push_pos_(State, P, H0, H) :-
    get_assoc(P, State, St),
    score_(P, St, Score),
    add_to_heap(H0, Score, P, H).

score_(P, st(info(_, _, _, N), U, B, _), s(Free, Unlinked, N, NegB, P)) :-
    (   U =:= 0
    ->  Free = 0
    ;   Free = 1
    ),
    (   B > 0
    ->  Unlinked = 0
    ;   Unlinked = 1
    ),
    NegB is -B.

order_loop_(Heap0, State0, Ctx, Bound0, Steps, TailTests) :-
    Ctx = ctx(Occ, PosIds, TestIdx),
    (   get_from_heap(Heap0, Score, P, Heap1)
    ->  get_assoc(P, State0, St),
        (   arg(4, St, open),
            score_(P, St, Score)
        ->  St = st(info(I, L, Cands, _), _, _, _),
            Steps = [lit(I, L, Cands, _)|Steps1],
            put_assoc(P, State0, st(info(I, L, Cands, 0), 0, 0, done), State1),
            get_assoc(P, PosIds, Vs),
            exclude(bound_var_(Bound0), Vs, NewVs),
            foldl(bind_var_(Occ), NewVs, State1-Heap1, State2-Heap2),
            foldl(mark_bound_, NewVs, Bound0, Bound1),
            foldl(new_tests_(TestIdx), NewVs, Steps1, Steps2),
            order_loop_(Heap2, State2, Ctx, Bound1, Steps2, TailTests)
        ;   order_loop_(Heap1, State0, Ctx, Bound0, Steps, TailTests)
        )
    ;   Steps = [],
        assoc_to_list(TestIdx, Pending),
        foldl(unbound_tests_(Bound0), Pending, TailTests, [])
    ).

unbound_tests_(Bound, V-Ts, Tail0, Tail) :-
    (   get_assoc(V, Bound, _)
    ->  Tail0 = Tail
    ;   append(Ts, Tail, Tail0)
    ).

bound_var_(Bound, V) :-
    get_assoc(V, Bound, _).

mark_bound_(V, B0, B) :-
    put_assoc(V, B0, true, B).

bind_var_(Occ, V, State0-Heap0, State-Heap) :-
    get_assoc(V, Occ, Ps),
    foldl(bump_, Ps, State0-Heap0, State-Heap).

bump_(P, State0-Heap0, State-Heap) :-
    get_assoc(P, State0, st(Info, U, B, Status)),
    (   Status == open
    ->  U1 is U - 1,
        B1 is B + 1,
        St1 = st(Info, U1, B1, open),
        put_assoc(P, State0, St1, State),
        score_(P, St1, Score),
        add_to_heap(Heap0, Score, P, Heap)
    ;   State = State0,
        Heap = Heap0
    ).

%   new_tests_(+TestIdx, +V, -Steps0, ?Steps): difference list of the test
%   steps on variable V (no findall/3: the tests hold live variables).
new_tests_(TestIdx, V, Steps0, Steps) :-
    (   get_assoc(V, TestIdx, Ts)
    ->  maplist(test_step_, Ts, TSteps),
        append(TSteps, Steps, Steps0)
    ;   Steps0 = Steps
    ).

%   dyn_search_(+Items, +Cands, +Tests, +Ranges, -Image): find one
%   substitution that maps every literal I-L of a component onto one of its
%   candidates J-C and passes the range tests; Image lists the J used.
%   Forward checking with dynamic ordering: at each node every open literal's
%   domain is cut to the candidates that still unify, a literal left with
%   no candidate fails the node at once, literals made ground with a
%   candidate left are settled without branching, and the branch is taken
%   on the literal with the fewest candidates. Tests run as soon as their
%   variable is bound.
dyn_search_(Items, Cands, Tests, Ranges, Excl, Image) :-
    maplist(dyn_lit_, Items, Cands, Lits),
    pairs_values(Tests, TestLits),
    once(dyn_(Lits, TestLits, Ranges-Excl)),
    maplist(arg(4), Lits, Image).

dyn_lit_(I-L, Cands, lit(I, L, Cands, _)).

dyn_([], Tests, Ranges-_) :-
    maplist(test_holds_(Ranges), Tests).
dyn_([L0|Ls0], Tests0, Ranges-Excl) :-
    bound_tests_(Tests0, Ranges, Tests),
    narrow_([L0|Ls0], Excl, Open, none, Best),
    (   Best == none
    ->  dyn_([], Tests, Ranges-Excl)
    ;   Best = lit(_, L, Cs, J)-_,
        exclude(==(Best), Open, Rest0),
        pairs_keys(Rest0, Rest),
        member(J-C, Cs),
        L = C,
        dyn_(Rest, Tests, Ranges-Excl)
    ).

test_holds_(Ranges, in_range(V, Lo, Hi)) :-
    range_test_(V, Lo, Hi, Ranges).

bound_tests_([], _, []).
bound_tests_([T|Ts], Ranges, Out) :-
    T = in_range(V, Lo, Hi),
    (   var(V)
    ->  Out = [T|Out1]
    ;   range_test_(V, Lo, Hi, Ranges),
        Out = Out1
    ),
    bound_tests_(Ts, Ranges, Out1).

%   narrow_(+Lits, -Open, +Best0, -Best): Open are the literals still to
%   branch on, each Lit-Size with its narrowed domain; settled ground
%   literals bind their J and leave; fails when a domain is empty.
narrow_([], _, [], Best, Best).
narrow_([lit(I, L, Cands, J)|Ls], Excl, Open, Best0, Best) :-
    include(unifiable_cand_(L, Excl), Cands, Cs),
    Cs = [J1-_|_],
    (   ground(L)
    ->  J = J1,
        narrow_(Ls, Excl, Open, Best0, Best)
    ;   length(Cs, N),
        Lit = lit(I, L, Cs, J)-N,
        Open = [Lit|Open1],
        (   Best0 == none
        ->  Best1 = Lit
        ;   Best0 = _-N0,
            N < N0
        ->  Best1 = Lit
        ;   Best1 = Best0
        ),
        narrow_(Ls, Excl, Open1, Best1, Best)
    ).

unifiable_cand_(L, Excl, J-C) :-
    \+ L \= C,
    \+ get_assoc(J, Excl, _).

