:- begin_tests(transfer, [setup(knowledge:load_default_ontology)]).

%   A hook model as a run's model.pl writes it (only its two bounds matter here).
hook_prior(prior(hook, HS, HG)) :-
    HS = (tool_pose(T, C, X) :- hook(T), handle_length(T, medium), hook_down(T),
          behind(T, C), centred_on(T, C), in_tube(T, X)),
    HG = (tool_pose(T, C, _) :- handle_length(T, medium), hook_down(T), behind(T, C),
          centred_on(T, C), hook(T)).

rake_demo((tool_pose(rake_a2, box1, shelf1) :-
           hook(rake_a2), handle_length(rake_a2, long), hook_down(rake_a2),
           behind(rake_a2, box1), centred_on(rake_a2, box1), hook_length(rake_a2, short),
           under_shelf(box1, shelf1))).

test(shared_same_kind) :-
    hook_prior(P),
    transfer:prior_shared(rake, P, S),
    length(S, 5).

%   The paddle shares the tube's spatial definitions, and gives its blade_upright the
%   meaning the hook gives hook_down (spatial_meaning/3): the literal takes its name.
test(shared_spatial_only) :-
    hook_prior(P),
    transfer:prior_shared(paddle_tube, P, S),
    assertion(S = [blade_upright(_), behind(_, _), centred_on(_, _)]).

test(shared_unrelated) :-
    hook_prior(P),
    transfer:prior_shared(wedge, P, S),
    assertion(S == []).

test(unknown_prior_case, [throws(error(existence_error(case, kitchen), _))]) :-
    transfer:prior_shared(hook, prior(kitchen, t, t), _).

%   The roles map through the head; another value (handle_length long) does not transfer.
test(literals_by_value) :-
    hook_prior(P),
    rake_demo(E),
    transfer:prior_literals(rake, P, E, L),
    assertion(L == [hook_down(rake_a2), behind(rake_a2, box1), centred_on(rake_a2, box1),
                    hook(rake_a2)]).

%   The demonstration violates the prior's handle_length(T, medium): contradicted.
test(contradicted_by_the_demonstration) :-
    hook_prior(P),
    rake_demo(E),
    transfer:prior_contradicted(rake, P, E, L),
    assertion(L == [handle_length(rake_a2, medium)]).

test(read_prior_missing, [throws(error(existence_error(file, '/nonexistent/model.pl'), _))]) :-
    transfer:read_prior('/nonexistent/model.pl', _).

test(read_prior_file) :-
    tmp_file_stream(text, F, Out),
    hook_prior(prior(_, HS, HG)),
    portray_clause(Out, learned_hypothesis(hook, hs, HS)),
    portray_clause(Out, learned_hypothesis(hook, hg, HG)),
    close(Out),
    transfer:read_prior(F, prior(Case, _, G)),
    delete_file(F),
    assertion(Case == hook),
    assertion(G = (tool_pose(_, _, _) :- _)).

%   The version space starts with the prior's literals in h_g; they are not unknown and
%   every hypothesis keeps them; a success that violates one drops it, noted.
test(vs_prior_start_and_drop) :-
    rake_demo(E),
    version_space:vs_init_prior(E, [hook_down(rake_a2), behind(rake_a2, box1)], VS),
    vs_unknown(VS, U),
    assertion(\+ memberchk(hook_down(_), U)),
    vs_count(VS, N, true),
    version_space:vs_init(E, VS0),
    vs_count(VS0, N0, true),
    assertion(N * 4 =:= N0),
    version_space:vs_prior(VS, Kept, []),
    assertion(length(Kept, 2)),
    vs_update(VS, pos((tool_pose(r3, box1, shelf1) :-
                       hook(r3), handle_length(r3, long), behind(r3, box1),
                       centred_on(r3, box1), hook_length(r3, short),
                       under_shelf(box1, shelf1))), VS1),
    version_space:vs_prior(VS1, Kept1, Dropped),
    assertion(Kept1 = [behind(_, _)]),
    assertion(Dropped = [hook_down(_)-_]),
    version_space:vs_prior_clause(VS1, (tool_pose(A, B, _) :- behind(A1, B1))),
    assertion(A == A1), assertion(B == B1).

test(no_prior_clause, [fail]) :-
    rake_demo(E),
    vs_init(E, VS),
    version_space:vs_prior_clause(VS, _).

:- end_tests(transfer).
