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

%   Task literals (not about the tool) and the case's untestable ones (the tool in the
%   tube) never transfer: no trial could confirm or contradict them.
test(no_task_or_untestable_literals) :-
    P = prior(hook, (tool_pose(T, C, X) :- hook(T)),
              (tool_pose(T, C, X) :- hook_down(T), in_tube(T, X), in_tube(C, X))),
    E = (tool_pose(hook_a2, cube1, tube1) :-
         hook(hook_a2), hook_down(hook_a2), in_tube(hook_a2, tube1),
         in_tube(cube1, tube1)),
    transfer:prior_literals(hook, P, E, L),
    assertion(L == [hook_down(hook_a2)]).

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

%   The prior's literals start open: h_g is empty as without a prior, they are still
%   unknown, and they constrain no hypothesis (the count is the count without a prior).
test(vs_prior_starts_open) :-
    rake_demo(E),
    version_space:vs_init_prior(E, [spatial-hook_down(rake_a2),
                                    spatial-behind(rake_a2, box1)], VS),
    vs_bounds(VS, _, HG),
    assertion(HG = tool_pose(_, _, _)),
    vs_unknown(VS, U),
    assertion(memberchk(hook_down(_), U)),
    vs_count(VS, N, true),
    version_space:vs_init(E, VS0),
    vs_count(VS0, N0, true),
    assertion(N == N0),
    version_space:vs_prior_open(VS, Open),
    assertion(Open == [3, 4]),
    version_space:vs_prior(VS, [], []).

r3_success((tool_pose(r3, box1, shelf1) :-
            hook(r3), handle_length(r3, medium), behind(r3, box1),
            centred_on(r3, box1), hook_length(r3, short), under_shelf(box1, shelf1))).

%   A success settles the open spatial literals it satisfies (h_g takes them, every
%   hypothesis keeps them) and drops those it violates; a structural literal is not
%   settled by a success: it stays open, to be tested.
test(vs_prior_settled_and_dropped) :-
    rake_demo(E),
    version_space:vs_init_prior(E, [spatial-hook_down(rake_a2),
                                    spatial-behind(rake_a2, box1),
                                    structural-hook_length(rake_a2, short)], VS),
    r3_success(P),
    vs_update(VS, pos(P), VS1),
    version_space:vs_prior(VS1, Kept, Dropped),
    assertion(Kept = [behind(_, _)]),
    assertion(Dropped = [hook_down(_)-_]),
    version_space:vs_prior_events(VS1, Events),
    assertion(Events = [dropped(hook_down(_), _), settled(behind(_, _), _)]),
    vs_bounds(VS1, _, (tool_pose(A, B, _) :- GBody)),
    assertion(GBody == behind(A, B)),
    version_space:vs_prior_open(VS1, Open),
    vs_space(VS1, _, Lits, Cs),
    assertion(( Open = [I], nth1(I, Lits, hook_length(_, short)) )),
    assertion(( nth1(J, Lits, behind(_, _)), memberchk([J], Cs) )),
    version_space:vs_prior_clause(VS1, (tool_pose(X, Y, _) :- behind(X1, Y1))),
    assertion(X == X1), assertion(Y == Y1).

%   A success that violates a wrong structural literal of the prior (one the
%   demonstration satisfies) drops it, recorded; h_g is what it is without the prior.
test(vs_prior_wrong_structural_dropped) :-
    rake_demo(E),
    version_space:vs_init_prior(E, [structural-handle_length(rake_a2, long),
                                    spatial-behind(rake_a2, box1)], VS),
    r3_success(P),
    vs_update(VS, pos(P), VS1),
    version_space:vs_prior_events(VS1, Events),
    assertion(Events = [dropped(handle_length(_, long), P), settled(behind(_, _), P)]).

%   A failure is learned from as without a prior, even when it also violates a
%   settled literal of the prior: the learned part of h_g is h_g without the prior
%   (hook_down here, first in h_s), not absorbed by the prior's centred_on, and h_g
%   adds the settled literal.
test(vs_prior_failure_not_absorbed) :-
    rake_demo(E),
    P = (tool_pose(r3, box1, shelf1) :-
         hook(r3), handle_length(r3, medium), hook_down(r3), behind(r3, box1),
         centred_on(r3, box1), hook_length(r3, short), under_shelf(box1, shelf1)),
    Fail = (tool_pose(r4, box1, shelf1) :-
            hook(r4), handle_length(r4, medium), behind(r4, box1),
            hook_length(r4, short), under_shelf(box1, shelf1)),
    version_space:vs_init_prior(E, [spatial-centred_on(rake_a2, box1)], VS0),
    vs_update(VS0, pos(P), VS1),
    vs_update(VS1, neg(Fail), VS2),
    vs_init(E, W0),
    vs_update(W0, pos(P), W1),
    vs_update(W1, neg(Fail), W2),
    vs_bounds(W2, _, (tool_pose(T0, _, _) :- WBody)),
    assertion(WBody == hook_down(T0)),
    vs_bounds(VS2, _, (tool_pose(T, C, _) :- GBody)),
    assertion(GBody == (hook_down(T), centred_on(T, C))).

test(no_prior_clause, [fail]) :-
    rake_demo(E),
    vs_init(E, VS),
    version_space:vs_prior_clause(VS, _).

:- end_tests(transfer).
