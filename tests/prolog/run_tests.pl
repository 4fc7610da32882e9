%   Load the engine and every .plt file of this folder, then run all plunit tests:
%
%       swipl --on-warning=status -q -g run_all -t halt tests/prolog/run_tests.pl
%
%   --on-warning=status makes load warnings and leftover choicepoints fail the run.

:- use_module(library(plunit)).
:- use_module(library(time), [call_with_time_limit/2]).
:- use_module(library(apply), [foldl/4]).
:- use_module(library(lists), [reverse/2]).

:- prolog_load_context(directory, Dir),
   file_directory_name(Dir, TestsDir),
   file_directory_name(TestsDir, Root),
   directory_file_path(Root, 'prolog/creative.pl', Engine),
   load_files(user:Engine, []),
   directory_files(Dir, Entries),
   msort(Entries, Sorted),
   forall(( member(E, Sorted), file_name_extension(_, plt, E) ),
          ( directory_file_path(Dir, E, Path), load_files(user:Path, []) )).

%   run_all: every unit in turn, each under a time limit (UNIT_LIMIT_S seconds), so a
%   test whose predicate loops fails its unit instead of hanging the run (SWI-Prolog
%   9.0's plunit has no per-test time limit).  Fails (exit status 1 under -g) if a unit
%   failed or ran out of time.
unit_limit_s(120).

run_all :-
    findall(U, current_test_unit(U, _), Units0),
    sort(Units0, Units),
    unit_limit_s(Limit),
    foldl(run_unit_limited_(Limit), Units, [], Bad),
    (   Bad == []
    ->  true
    ;   reverse(Bad, Failed),
        format(user_error, "plunit units failed or out of time: ~w~n", [Failed]),
        fail
    ).

run_unit_limited_(Limit, Unit, Bad0, Bad) :-
    (   catch(call_with_time_limit(Limit, run_tests(Unit)),
              time_limit_exceeded,
              ( format(user_error, "plunit unit ~w ran over ~w s: a test loops~n",
                       [Unit, Limit]),
                fail ))
    ->  Bad = Bad0
    ;   Bad = [Unit|Bad0]
    ).
