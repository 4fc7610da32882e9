%   Run the plunit suite of a copy of the repository (mutants.py), the units of
%   the mutated module first, and stop at the first test that fails or runs out
%   of time: exit status 1 (killed), 0 when every test passed (survived).
%
%       swipl -q -g "first_failure([lgg, lgg_equivalence])" -t halt \
%             COPY/tests/prolog/mutants/first_failure.pl

:- prolog_load_context(directory, Dir),
   file_directory_name(Dir, TestsDir),
   directory_file_path(TestsDir, 'run_tests.pl', Runner),
   load_files(user:Runner, []).

first_failure(First) :-
    findall(U:T, current_test(U, T, _, _, _), Tests),
    partition(in_units_(First), Tests, Front, Back),
    append(Front, Back, Ordered),
    test_limit_s(Limit),
    (   member(Test, Ordered),
        \+ run_test_limited_(Limit, Test, [], [])
    ->  format(user_error, "killed by ~w~n", [Test]),
        halt(1)
    ;   halt(0)
    ).

in_units_(Units, U:_) :-
    memberchk(U, Units).
