:- module(lgg_reference,
          [ ref_clause_lgg/3,        % +C1, +C2, -G
            ref_lgg_unreduced/3,     % +C1, +C2, -Raw
            ref_clause_reduce/2,     % +Clause, -Reduced
            ref_clause_reduce/3      % +Clause, -Reduced, +Options
          ]).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(assoc)).
:- use_module(library(option)).
:- use_module(library(pairs)).
:- use_module(library(ordsets)).
:- use_module('../../../prolog/subsumption', [clause_head_body/3]).

/** <module> Reference implementation of clause_lgg/3 and clause_reduce/2 (tests only)

The algorithms of lgg:clause_lgg/3 and subsumption:clause_reduce/2,3 as they
were before the faster versions of issue 18 (commit e8716e0): head
connection by repeated passes over the body, and a reduction that scans the
whole candidate list of every literal and the whole component for every
redundancy test. Kept verbatim (only renamed) so that tests/prolog/lgg_equivalence.plt
can check that the engine's results are unchanged, up to variable renaming.
Nothing in prolog/ loads this file.
*/

ref_clause_head_body(C, H, B) :-
    clause_head_body(C, H, B).

ref_clause_lgg(C1, C2, G) :-
    ref_lgg_unreduced(C1, C2, Raw),
    ref_clause_reduce(Raw, G).

%   ref_lgg_unreduced(+C1, +C2, -Raw): the head-connected LGG before reduction.
ref_lgg_unreduced(C1, C2, Raw) :-
    ref_clause_head_body(C1, H1, B1),
    ref_clause_head_body(C2, H2, B2),
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
    ref_clause_head_body(Raw, UH, Body).

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
%   linked to the head's variables through shared variables.
head_connected_(Head, Lits, Kept) :-
    copy_term_nat(Head-Lits, CHead-CLits),
    numbervars(CHead-CLits, 0, _, [functor_name('$hc')]),
    var_ids_(CHead, HeadIds),
    maplist(var_ids_, CLits, LitIds),
    pairs_keys_values(Pairs, LitIds, Lits),
    connect_(Pairs, HeadIds, Flags),
    pairs_keys_values(Flagged, Flags, Lits),
    include(kept_flag_, Flagged, KeptPairs),
    pairs_values(KeptPairs, Kept).

var_ids_(T, Ids) :-
    findall(N, sub_term('$hc'(N), T), Ns),
    sort(Ns, Ids).

connect_(Pairs, Connected0, Flags) :-
    foldl(connect_step_, Pairs, Flags0, Connected0-false, Connected-Changed),
    (   Changed == true
    ->  connect_(Pairs, Connected, Flags)
    ;   Flags = Flags0
    ).

connect_step_(Ids-_, Flag, C0-Ch0, C-Ch) :-
    (   Ids == []
    ->  Flag = kept,
        C = C0,
        Ch = Ch0
    ;   ord_intersect(Ids, C0)
    ->  Flag = kept,
        ord_union(C0, Ids, C),
        (   C == C0
        ->  Ch = Ch0
        ;   Ch = true
        )
    ;   Flag = dropped,
        C = C0,
        Ch = Ch0
    ).

kept_flag_(kept-_).

% ---------------------------------------------------------------------------
% Old clause_reduce/2,3 (subsumption.pl)

ref_clause_reduce(Clause, Reduced) :-
    ref_clause_reduce(Clause, Reduced, []).

ref_clause_reduce(Clause, Reduced, Options) :-
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
    ref_clause_head_body(Clause, Head, Body0),
    list_to_set(Body0, Body),
    split_body_(Body, Lits, Tests),
    number_items_(Lits, 1, Items),
    number_items_(Tests, 1, TestItems),
    reduce_items_(Head, Items, TestItems, TestLimit-FullMax-OnLimit, KeptItems),
    pairs_values(KeptItems, Kept),
    term_variables(Head-Kept, Live),
    include(live_test_(Live), Tests, KeptTests),
    append(Kept, KeptTests, RBody),
    ref_clause_head_body(Reduced, Head, RBody).

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
    spec_index_(SItems, Index),
    pairs_values(STests, STestLits),
    spec_ranges_(STestLits, Ranges),
    copy_term_nat(Head-Items-Tests, CH-CItems-CTests),
    CH = SH,
    components_(CItems, CTests, Comps),
    empty_assoc(NoExcl),
    maplist(candidates_(Index, NoExcl), CItems, CandLists),
    pairs_keys(Items, Idxs),
    pairs_keys_values(CandPairs, Idxs, CandLists),
    list_to_assoc(CandPairs, CandAll),
    list_to_assoc(Items, ItemAssoc),
    list_to_assoc(SItems, SAssoc),
    skolem_occurrences_(SItems, SkOcc),
    skolems_in_(SH, HeadSks),
    empty_assoc(Removed0),
    Ctx = red(Head, ItemAssoc, Tests, SH, CandAll, Ranges, TestLimit-FullMax, OnLimit,
              local(SAssoc, SkOcc, HeadSks, STests)),
    foldl(reduce_component_(Ctx), Comps, Removed0, Removed),
    exclude(removed_item_(Removed), Items, Kept).

removed_item_(Removed, I-_) :-
    get_assoc(I, Removed, _).

reduce_component_(Ctx, comp(CItems, _), Removed0, Removed) :-
    pairs_keys(CItems, Idxs),
    (   CItems = [_-L],
        ground(L)
    ->  Removed = Removed0
    ;   foldl(reduce_literal_(Ctx, Idxs), Idxs, Removed0, Removed)
    ).

%   Literal I goes when its component maps into the clause without I (and
%   without the literals removed so far); a literal whose only possible
%   image is itself is skipped at once.
reduce_literal_(Ctx, Idxs, I, Removed0, Removed) :-
    Ctx = red(_, _, _, _, CandAll, _, _, _, _),
    (   get_assoc(I, Removed0, _)
    ->  Removed = Removed0
    ;   get_assoc(I, CandAll, OwnCands),
        \+ ( member(J-_, OwnCands), J =\= I, \+ get_assoc(J, Removed0, _) )
    ->  Removed = Removed0
    ;   put_assoc(I, Removed0, true, Excl),
        (   redundant_literal_(Ctx, I, Idxs, Excl, Gone)
        ->  foldl(mark_removed_, Gone, Removed0, Removed)
        ;   Removed = Removed0
        )
    ).

%   redundant_literal_(+Ctx, +I, +Idxs, +Excl, -Gone): some substitution
%   maps the component Idxs (less the removed literals) into the clause without literal I; Gone are
%   the literals of Alive outside its image (I among them). First the
%   local test: every variable except the non-head variables of literal I
%   stays itself, so only the literals that contain those variables are
%   searched (cheap, and it finds most redundancies). Then, for components
%   of at most full_test_max literals, the full test of the component,
%   bounded by test_limit: when the bound is hit the literal is kept (the
%   clause stays equivalent, only perhaps not minimal), unless
%   on_limit(error) was given.
redundant_literal_(Ctx, I, Idxs, Excl, Gone) :-
    Ctx = red(Head, ItemAssoc, Tests, SH, CandAll, Ranges, Limit-FullMax, OnLimit, _),
    (   findall(G, local_gone_(Ctx, I, Excl, G), [Gone0|_])
    ->  Gone = Gone0
    ;   exclude(removed_key_(Excl), Idxs, Alive0),
        Alive = [I|Alive0],
        length(Alive, NAlive),
        NAlive =< FullMax,
        maplist(item_at_(ItemAssoc), Alive, KItems0),
        copy_term_nat(Head-KItems0-Tests, GH-KItems-GTests),
        GH = SH,
        term_variables(KItems, KVars),
        include(test_on_(KVars), GTests, KTests),
        maplist(all_candidates_(CandAll), Alive, CandLists),
        bounded_test_(Limit, OnLimit,
                      reduce_match_(KItems, CandLists, KTests, Ranges, Excl, Image)),
        subtract_idx_(Alive, Image, Gone)
    ).

local_gone_(Ctx, I, Excl, Gone) :-
    Ctx = red(_, _, _, _, CandAll, Ranges, Limit-_, _,
              local(SAssoc, SkOcc, HeadSks, STests)),
    get_assoc(I, SAssoc, SI),
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
    maplist(all_candidates_(CandAll), NearIdx, CandLists),
    pairs_values(STests, STestLits),
    include(local_test_(Map), STestLits, NTests0),
    maplist(unskolem_(Map), NTests0, NTests1),
    number_items_(NTests1, 1, NTests),
    bounded_test_(Limit, keep,
                  reduce_match_(NearItems, CandLists, NTests, Ranges, Excl, NearImage)),
    subtract_idx_(NearIdx, NearImage, Gone).

general_item_(SAssoc, Map, J, J-L) :-
    get_assoc(J, SAssoc, SL),
    unskolem_(Map, SL, L).

local_test_(Map, in_range(Sk, _, _)) :-
    get_assoc(Sk, Map, _).

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

all_candidates_(CandAll, I, Cands) :-
    get_assoc(I, CandAll, Cands).

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

components_(Items, Tests, Comps) :-
    copy_term_nat(Items, CItems),
    numbervars(CItems, 0, _, [functor_name('$cv')]),
    maplist(item_var_ids_, CItems, IdItems),
    var_occurrences_(IdItems, Occ),
    empty_assoc(Seen0),
    group_items_(Items, IdItems, Occ, Seen0, Groups),
    foldl(group_comp_(Items), Groups, Comps0, Tests, Lone),
    maplist(lone_comp_, Lone, LoneComps),
    append(Comps0, LoneComps, Comps).

lone_comp_(T, comp([], [T])).

item_var_ids_(I-L, I-Ids) :-
    findall(N, sub_term('$cv'(N), L), Ns),
    sort(Ns, Ids).

var_occurrences_(IdItems, Occ) :-
    findall(V-I, ( member(I-Ids, IdItems), member(V, Ids) ), Pairs0),
    keysort(Pairs0, Pairs),
    group_pairs_by_key(Pairs, Groups),
    list_to_assoc(Groups, Occ).

group_items_([], _, _, _, []).
group_items_([I-_|Items], IdItems, Occ, Seen0, Groups) :-
    (   get_assoc(I, Seen0, _)
    ->  group_items_(Items, IdItems, Occ, Seen0, Groups)
    ;   closure_([I], IdItems, Occ, Seen0, Seen, [], Group0),
        sort(Group0, Group),
        Groups = [Group|Groups1],
        group_items_(Items, IdItems, Occ, Seen, Groups1)
    ).

closure_([], _, _, Seen, Seen, Acc, Acc).
closure_([I|Is], IdItems, Occ, Seen0, Seen, Acc0, Acc) :-
    (   get_assoc(I, Seen0, _)
    ->  closure_(Is, IdItems, Occ, Seen0, Seen, Acc0, Acc)
    ;   put_assoc(I, Seen0, true, Seen1),
        memberchk(I-Ids, IdItems),
        findall(J, ( member(V, Ids), get_assoc(V, Occ, Js), member(J, Js) ), Next),
        append(Next, Is, Queue),
        closure_(Queue, IdItems, Occ, Seen1, Seen, [I|Acc0], Acc)
    ).

group_comp_(Items, Group, comp(GItems, GTests), Tests0, Tests) :-
    include(in_group_(Group), Items, GItems),
    term_variables(GItems, Vars),
    partition(test_on_(Vars), Tests0, GTests, Tests).

in_group_(Group, I-_) :-
    memberchk(I, Group).

test_on_(Vars, _-in_range(V, _, _)) :-
    var(V),
    member(W, Vars),
    W == V,
    !.

candidates_(Index, Excl, _-L, Cands) :-
    lit_key_(L, Key),
    (   get_assoc(Key, Index, All)
    ->  include(candidate_ok_(L, Excl), All, Cands)
    ;   Cands = []
    ).

candidate_ok_(L, Excl, J-C) :-
    \+ get_assoc(J, Excl, _),
    \+ L \= C.

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

