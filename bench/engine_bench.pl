/*  Benchmark of the ILP core: clause_lgg/3, theta_subsumes/2, clause_reduce/2,
    nbr_reduce/3 on generated clauses of 10, 50, 100 and 200 body literals, and
    one vs_update/3 at the hook case's size.

    clause_lgg/3 is also timed with the algorithm it replaced (issue 18: head
    connection by repeated passes, a reduction that rescans candidate lists),
    kept in tests/prolog/reference/lgg_reference.pl, and the two results are
    compared up to variable renaming: `clause_lgg_same_as_reference` with the
    default bounds of clause_reduce/3, `reduction_same_unbounded` for the
    reduction of the same unreduced LGG with test_limit(infinite) (the old
    reduction's local tests are cut by their inference bound at 100 and 200
    literals, where the new one finishes them).

        swipl bench/engine_bench.pl [--out FILE | --record]

    Prints a table (milliseconds, median of several runs of wall time);
    --out FILE writes its figures (JSON) to FILE, --record to the tracked
    bench/results/engine.json (as bench/recording.py does for the Python
    benchmarks: a tracked file is only overwritten when asked). The clauses are generated with a fixed
    seed: scenes of objects with kinds, qualitative sizes, measured lengths
    (numbers), binary relations that share objects, and a few negated
    literals, so every predicate occurs many times at the larger sizes. The
    LGG pairs a scene with a perturbed copy of itself (objects renamed,
    numbers moved, one literal in five replaced): two examples of one concept.
*/

:- initialization(main, main).

:- prolog_load_context(directory, Dir),
   file_directory_name(Dir, Root),
   directory_file_path(Root, 'prolog/creative.pl', Engine),
   load_files(user:Engine, [if(not_loaded)]),
   directory_file_path(Root, 'tests/prolog/reference/lgg_reference.pl', Ref),
   use_module(Ref).

:- use_module(library(random)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(http/json)).

sizes([10, 50, 100, 200]).

main :-
    current_prolog_flag(argv, Argv),
    (   memberchk('--help', Argv)
    ->  format("usage: swipl bench/engine_bench.pl [--out FILE | --record]~n"),
        format("  --out FILE  write the figures (JSON) to FILE (default: only print)~n"),
        format("  --record    write them to the tracked bench/results/engine.json~n")
    ;   sizes(Sizes),
        maplist(bench_size, Sizes, Rows),
        bench_vs_update(VsRow),
        print_table(Rows, VsRow),
        current_prolog_flag(version, V),
        Dict = _{ benchmark: "engine", unit: "ms", statistic: "median wall time",
                  swipl_version: V, sizes: Rows, vs_update: VsRow },
        write_figures(Argv, Dict)
    ).

%   write_figures(+Argv, +Dict) is det: write Dict (JSON) where --out or
%   --record says, or say that nothing was written.
write_figures(Argv, Dict) :-
    (   output_file(Argv, Out)
    ->  file_directory_name(Out, OutDir),
        make_directory_path(OutDir),
        setup_call_cleanup(open(Out, write, S),
                           json_write_dict(S, Dict, [width(100)]),
                           close(S)),
        format("~nfigures written to ~w~n", [Out])
    ;   format("~nfigures not written (give --out FILE, or --record to update the \c
                tracked bench/results/engine.json)~n")
    ).

output_file(Argv, File) :-
    append(_, ['--out', File|_], Argv),
    !.
output_file(Argv, File) :-
    memberchk('--record', Argv),
    prolog_load_context_root(Root),
    directory_file_path(Root, 'bench/results/engine.json', File).

prolog_load_context_root(Root) :-
    source_file(main, File),
    file_directory_name(File, Dir),
    file_directory_name(Dir, Root).

% ---------------------------------------------------------------------------
% Generated clauses

%   scene(+Seed, +N, -Example): a ground example clause with N body literals
%   about the objects o0..oK; the head's objects are o0, o1, o2.
scene(Seed, N, Example) :-
    set_random(seed(Seed)),
    K is max(4, N // 4),
    length(Body, N),
    maplist(random_literal(K), Body),
    Example = (tool_pose(o0, o1, o2) :- Conj),
    list_conj(Body, Conj).

random_literal(K, L) :-
    random_between(0, 9, Kind),
    random_between(0, K, A),
    random_between(0, K, B),
    atom_concat(o, A, OA),
    atom_concat(o, B, OB),
    literal_of_kind(Kind, OA, OB, L).

literal_of_kind(0, A, _, kind(A, K)) :- random_member(K, [hook, stick, cube, tube]).
literal_of_kind(1, A, _, size_class(A, S)) :- random_member(S, [short, medium, long]).
literal_of_kind(2, A, _, length_m(A, X)) :- random_between(10, 70, C), X is C / 100.
literal_of_kind(3, A, _, width_m(A, X)) :- random_between(6, 30, M), X is M / 1000.
literal_of_kind(4, A, B, touches(A, B)).
literal_of_kind(5, A, B, left_of(A, B)).
literal_of_kind(6, A, B, inside(A, B)).
literal_of_kind(7, A, B, behind(A, B)).
literal_of_kind(8, A, _, \+ broken(A)).
literal_of_kind(9, A, B, attached(A, B, Side)) :- random_member(Side, [left, right]).

list_conj([L], L) :- !.
list_conj([L|Ls], (L, C)) :- list_conj(Ls, C).

%   perturbed(+Example, +Seed, -Other): a second example of the same
%   concept: the objects renamed (o_i -> p_i, the head's objects too), every
%   number moved by up to 20 %, and one literal in five replaced by a random
%   one, so the two examples share most of their structure.
perturbed(Example, Seed, Other) :-
    clause_head_body(Example, H0, B0),
    set_random(seed(Seed)),
    length(B0, N),
    K is max(4, N // 4),
    maplist(perturb_literal(K), B0, B1),
    clause_head_body(E1, H0, B1),
    rename_objects(E1, Other).

perturb_literal(K, L0, L) :-
    random_between(1, 5, R),
    (   R =:= 1
    ->  random_literal(K, L)
    ;   perturb_numbers(L0, L)
    ).

perturb_numbers(T0, T) :-
    (   float(T0)
    ->  random_between(80, 120, P),
        T is T0 * P / 100
    ;   compound(T0)
    ->  T0 =.. [F|As0],
        maplist(perturb_numbers, As0, As),
        T =.. [F|As]
    ;   T = T0
    ).

rename_objects(T0, T) :-
    (   atom(T0),
        atom_concat(o, Num, T0),
        atom_number(Num, _)
    ->  atom_concat(p, Num, T)
    ;   compound(T0)
    ->  T0 =.. [F|As0],
        maplist(rename_objects, As0, As),
        T =.. [F|As]
    ;   T = T0
    ).

%   variabilise(+Ground, -Clause): every object constant becomes a variable.
variabilise(Ground, Clause) :-
    findall(O, ( sub_term(O, Ground), atom(O), sub_atom(O, 0, 1, _, o),
                 atom_length(O, Len), Len > 1 ), Os0),
    sort(Os0, Os),
    length(Os, NO),
    length(Vs, NO),
    pairs_keys_values(Map, Os, Vs),
    replace(Map, Ground, Clause).

replace(Map, T0, T) :-
    (   atom(T0), memberchk(T0-V, Map)
    ->  T = V
    ;   compound(T0)
    ->  T0 =.. [F|As0],
        maplist(replace(Map), As0, As),
        T =.. [F|As]
    ;   T = T0
    ).

%   redundant(+Clause, -Bigger): Clause plus one more general copy of every
%   other binary literal (an argument replaced by a fresh variable), which
%   reduction must remove again.
redundant(Clause, Bigger) :-
    clause_head_body(Clause, H, B),
    findall(I-L, nth1(I, B, L), Indexed),
    foldl(add_general, Indexed, [], Extra0),
    reverse(Extra0, Extra),
    append(B, Extra, B2),
    clause_head_body(Bigger, H, B2).

add_general(I-L, Acc, Acc1) :-
    (   I mod 2 =:= 0,
        compound(L),
        L \= (\+ _),
        L =.. [F, A, _|Rest]
    ->  G =.. [F, A, _|Rest],
        Acc1 = [G|Acc]
    ;   Acc1 = Acc
    ).

%   negatives(+Example, +M, -Negs): M near misses of Example, each with a
%   few body literals removed, so that the variabilised example covers none.
negatives(Example, M, Negs) :-
    clause_head_body(Example, H, B),
    numlist(1, M, Is),
    maplist(near_miss(H, B), Is, Negs).

near_miss(H, B, I, Neg) :-
    set_random(seed(I)),
    length(B, N),
    Drop is max(1, N // 10),
    findall(J, ( between(1, Drop, _), random_between(1, N, J) ), Js),
    findall(L, ( nth1(J, B, L), \+ memberchk(J, Js) ), B1),
    clause_head_body(Neg, H, B1).

% ---------------------------------------------------------------------------
% Timing

median_ms(Runs, Goal, Ms) :-
    numlist(1, Runs, Is),
    maplist(time_once(Goal), Is, Ts),
    msort(Ts, Sorted),
    length(Sorted, N),
    Mid is N // 2,
    nth0(Mid, Sorted, Ms).

time_once(Goal, _, Ms) :-
    garbage_collect,
    get_time(T0),
    (   call(Goal)
    ->  true
    ;   true
    ),
    get_time(T1),
    Ms is (T1 - T0) * 1000.

runs(N, Runs) :-
    (   N =< 50
    ->  Runs = 9
    ;   N =< 100
    ->  Runs = 5
    ;   Runs = 3
    ).

bench_size(N, Row) :-
    runs(N, Runs),
    scene(1, N, E1),
    perturbed(E1, 2, E2),
    variabilise(E1, C1),
    (   N >= 200
    ->  RefRuns = 1
    ;   RefRuns = Runs
    ),
    LggRuns = Runs,
    median_ms(LggRuns, clause_lgg(E1, E2, _), Lgg),
    median_ms(RefRuns, ref_clause_lgg(E1, E2, _), RefLgg),
    clause_lgg(E1, E2, G),
    clause_head_body(G, _, GB),
    length(GB, GLen),
    ref_clause_lgg(E1, E2, RG),
    clause_head_body(RG, _, RGB),
    length(RGB, RGLen),
    same_(G, RG, Same),
    ref_lgg_unreduced(E1, E2, Raw),
    clause_reduce(Raw, UG, [test_limit(infinite)]),
    ref_clause_reduce(Raw, URG, [test_limit(infinite)]),
    same_(UG, URG, SameUnbounded),
    median_ms(Runs, theta_subsumes(C1, E1), Sub),
    median_ms(Runs, \+ theta_subsumes(C1, E2), SubFail),
    redundant(C1, Big),
    clause_head_body(Big, _, BigB),
    length(BigB, BigLen),
    median_ms(Runs, clause_reduce(Big, _), Red),
    clause_reduce(Big, R),
    clause_head_body(R, _, RB),
    length(RB, RLen),
    negatives(E1, 10, Negs),
    median_ms(Runs, nbr_reduce(C1, Negs, _), Nbr),
    nbr_reduce(C1, Negs, NR),
    clause_head_body(NR, _, NRB),
    length(NRB, NRLen),
    Row = _{ body_literals: N, runs: Runs, clause_lgg_runs: LggRuns,
             clause_lgg_ms: Lgg, lgg_body_literals: GLen,
             clause_lgg_reference_ms: RefLgg, clause_lgg_reference_runs: RefRuns,
             reference_lgg_body_literals: RGLen,
             clause_lgg_same_as_reference: Same, reduction_same_unbounded: SameUnbounded,
             theta_subsumes_ms: Sub, theta_subsumes_failing_ms: SubFail,
             clause_reduce_ms: Red, reduce_input_literals: BigLen,
             reduce_output_literals: RLen,
             nbr_reduce_ms: Nbr, nbr_negatives: 10, nbr_output_literals: NRLen }.

same_(A, B, Same) :-
    (   A =@= B
    ->  Same = true
    ;   Same = false
    ).

% ---------------------------------------------------------------------------
% One vs_update at the hook case's size

hook_example(Tool, HL, HLm, Spatial, E) :-
    Lits = [ tool(Tool), hook_like(Tool), hook(Tool), handle_length(Tool, HL),
             handle_width(Tool, thin), hook_length(Tool, long), hook_width(Tool, wide),
             hook_side(Tool, right), hook_angle(Tool, right), handle_length_m(Tool, HLm),
             handle_width_m(Tool, 0.01), hook_length_m(Tool, 0.03), hook_width_m(Tool, 0.01),
             hook_angle_deg(Tool, 90), in_tube(Tool, context1), in_tube(target1, context1),
             size(target1, 0.03, 0.03, 0.03), tube_length_m(context1, 0.3) | Spatial ],
    clause_head_body(E, tool_pose(Tool, target1, context1), Lits).

bench_vs_update(Row) :-
    hook_example(tool_2, medium, 0.35, [behind(tool_2, target1), hook_down(tool_2), centred_on(tool_2, target1)], E0),
    hook_example(tool_3, long, 0.5, [behind(tool_3, target1), hook_down(tool_3), centred_on(tool_3, target1)], P),
    hook_example(tool_2, medium, 0.35, [in_front(tool_2, target1), hook_down(tool_2), centred_on(tool_2, target1)], N1),
    hook_example(tool_4, medium, 0.3, [behind(tool_4, target1), hook_flat(tool_4), centred_on(tool_4, target1)], N2),
    clause_head_body(E0, _, B0),
    length(B0, Len),
    vs_init(E0, VS0),
    vs_update(VS0, neg(N1), VS1),
    median_ms(21, vs_update(VS1, pos(P), _), PosMs),
    median_ms(21, vs_update(VS1, neg(N2), _), NegMs),
    median_ms(21, vs_unknown(VS1, _), UnkMs),
    Row = _{ example_body_literals: Len, runs: 21,
             pos_update_ms: PosMs, neg_update_ms: NegMs, vs_unknown_ms: UnkMs }.

% ---------------------------------------------------------------------------

print_table(Rows, Vs) :-
    format("~w~t~8|~w~t~22|~w~t~36|~w~t~50|~w~t~66|~w~n",
           ['body', 'clause_lgg', 'theta_subs', 'theta(fail)', 'clause_reduce', 'nbr_reduce']),
    forall(member(R, Rows),
           format("~w~t~8|~2f~t~22|~2f~t~36|~2f~t~50|~2f~t~66|~2f~n",
                  [R.body_literals, R.clause_lgg_ms, R.theta_subsumes_ms,
                   R.theta_subsumes_failing_ms, R.clause_reduce_ms, R.nbr_reduce_ms])),
    findall(L, ( member(R, Rows), get_dict(lgg_body_literals, R, L) ), Ls),
    findall(I/O, ( member(R, Rows), get_dict(reduce_input_literals, R, I),
                   get_dict(reduce_output_literals, R, O) ), Rs),
    findall(O, ( member(R, Rows), get_dict(nbr_output_literals, R, O) ), Ns),
    format("(ms, median; lgg output literals: ~w; reduce in/out: ~w; nbr out: ~w)~n",
           [Ls, Rs, Ns]),
    forall(member(R, Rows),
           format("clause_lgg at ~w: ~2f ms, before issue 18 ~2f ms (~w literals, ~w); same: ~w, same with unbounded tests: ~w~n",
                  [R.body_literals, R.clause_lgg_ms, R.clause_lgg_reference_ms,
                   R.reference_lgg_body_literals, R.lgg_body_literals,
                   R.clause_lgg_same_as_reference, R.reduction_same_unbounded])),
    format("vs_update, hook case (~w body literals): pos ~2f ms, neg ~2f ms; vs_unknown ~3f ms~n",
           [Vs.example_body_literals, Vs.pos_update_ms, Vs.neg_update_ms, Vs.vs_unknown_ms]).
