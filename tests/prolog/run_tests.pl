%   Load the engine and every .plt file of this folder, then run all plunit tests:
%
%       swipl --on-warning=status -q -g run_all -t halt tests/prolog/run_tests.pl
%
%   --on-warning=status makes load warnings and leftover choicepoints fail the run.

:- use_module(library(plunit)).

:- prolog_load_context(directory, Dir),
   file_directory_name(Dir, TestsDir),
   file_directory_name(TestsDir, Root),
   directory_file_path(Root, 'prolog/creative.pl', Engine),
   load_files(user:Engine, []),
   directory_files(Dir, Entries),
   msort(Entries, Sorted),
   forall(( member(E, Sorted), file_name_extension(_, plt, E) ),
          ( directory_file_path(Dir, E, Path), load_files(user:Path, []) )).

run_all :-
    run_tests.
