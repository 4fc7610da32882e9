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

%   run_all: every test in turn, each under a time limit (test_limit_s/1 seconds), so a
%   test whose predicate loops fails instead of hanging the run (SWI-Prolog 9.0's
%   plunit has no time limit of its own).  Fails (exit status 1 under -g) if a test
%   failed or ran out of time, naming them.
test_limit_s(60).

%   Each passing test prints one dot, all on one line (plunit's silent option: no line
%   per test), then a count; a failing test prints its message as usual.
run_all :-
    findall(U:T, current_test(U, T, _, _, _), Tests),
    test_limit_s(Limit),
    set_test_options([silent(true)]),
    foldl(run_test_limited_(Limit), Tests, [], Bad),
    length(Tests, N),
    length(Bad, NBad),
    format(user_error, "~n~w plunit tests, ~w failed~n", [N, NBad]),
    (   Bad == []
    ->  true
    ;   reverse(Bad, Failed),
        format(user_error, "plunit tests failed or out of time: ~w~n", [Failed]),
        fail
    ).

run_test_limited_(Limit, Test, Bad0, Bad) :-
    (   catch(call_with_time_limit(Limit, run_tests(Test)),
              time_limit_exceeded,
              ( format(user_error, "plunit test ~w ran over ~w s: it loops~n",
                       [Test, Limit]),
                fail ))
    ->  Bad = Bad0
    ;   Bad = [Test|Bad0]
    ).
