:- begin_tests(model_file).

:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(readutil)).
:- use_module('fixtures/primitive_fixtures').

%   The hook demonstration's version space after failures that each violated one
%   literal: h_g = handle_length(T, medium), hook_side(T, right), behind(T, C),
%   centred_on(T, C), hook_down(T).  NewModels is the observed pull_out model.
learned_hook_(VS, NewModels) :-
    fixture_demonstration_vs(hook, VS0, NewModels),
    vs_examples(VS0, [E], _),
    fixture_variant_example(E, hook_a1,
                            [handle_length(hook_a1, medium)-handle_length(hook_a1, short)],
                            N1),
    fixture_variant_example(E, hook_a4,
                            [hook_side(hook_a4, right)-hook_side(hook_a4, left)], N2),
    fixture_variant_example(E, hook_a2,
                            [behind(hook_a2, cube1)-in_front(hook_a2, cube1)], N3),
    fixture_variant_example(E, hook_a2, [centred_on(hook_a2, cube1)-none], N4),
    fixture_variant_example(E, hook_a2, [hook_down(hook_a2)-hook_flat(hook_a2)], N5),
    foldl(add_negative_, [N1, N2, N3, N4, N5], VS0, VS).

%   The wedge demonstration's version space after failures with the wedge not near the
%   door, near the hinge, reversed, a box and a short wedge.
learned_wedge_(VS, NewModels) :-
    fixture_demonstration_vs(wedge, VS0, NewModels),
    vs_examples(VS0, [E], _),
    fixture_variant_example(E, wedge_a2, [near(wedge_a2, door1)-far(wedge_a2, door1)], N1),
    fixture_variant_example(E, wedge_a2,
                            [far_from_hinge(wedge_a2, door1)-near_hinge(wedge_a2, door1)],
                            N2),
    fixture_variant_example(E, wedge_a2,
                            [tip_towards(wedge_a2, door1)-tip_away(wedge_a2, door1)], N3),
    fixture_variant_example(E, box_a1, [shape(box_a1, triangular_prism)-shape(box_a1, box)],
                            N4),
    fixture_variant_example(E, wedge_a1,
                            [block_length(wedge_a1, long)-block_length(wedge_a1, short)],
                            N5),
    foldl(add_negative_, [N1, N2, N3, N4, N5], VS0, VS).

add_negative_(E, VS0, VS) :-
    vs_update(VS0, neg(E), VS).

%   Only the short-handled hook failed: h_g = handle_length(T, medium).
short_hook_failed_(VS, NewModels) :-
    fixture_demonstration_vs(hook, VS0, NewModels),
    vs_examples(VS0, [E], _),
    fixture_variant_example(E, hook_a1,
                            [handle_length(hook_a1, medium)-handle_length(hook_a1, short)],
                            Neg),
    vs_update(VS0, neg(Neg), VS).

temp_file_(File) :-
    tmp_file_stream(text, File, Out),
    close(Out).

temp_file_with_(Text, File) :-
    tmp_file_stream(text, File, Out),
    write(Out, Text),
    close(Out).

%   Load a model file into a clean knowledge base and collect what it holds.
loaded_models_(File, Task, Models) :-
    kb_reset,
    load_model_file(File),
    findall(learned_model(Task, A, P, E), learned_model(Task, A, P, E), Models).

cleanup_(File) :-
    kb_reset,
    (   exists_file(File)
    ->  delete_file(File)
    ;   true
    ).

                 /*******************************
                 *        WRITE AND LOAD        *
                 *******************************/

test(round_trip, [ setup(temp_file_(File)), cleanup(cleanup_(File)) ]) :-
    short_hook_failed_(VS, Models),
    write_model_file(File, hook, Models, VS),
    loaded_models_(File, hook, Loaded),
    assertion(Loaded =@= [learned_model(hook, pull_out(T, C, X),
                                        [holding(T), in_tube(C, X),
                                         handle_length(T, medium), in_tube(T, X),
                                         behind(T, C), centred_on(T, C), hook_down(T)],
                                        [add(out_of_tube(C, X)), del(in_tube(T, X)),
                                         del(in_tube(C, X))])]),
    findall(B, learned_hypothesis(hook, B, _), Bounds),
    assertion(Bounds == [hs, hg]),
    vs_bounds(VS, HS, HG),
    learned_hypothesis(hook, hs, LoadedHS),
    learned_hypothesis(hook, hg, LoadedHG),
    assertion(LoadedHS =@= HS),
    assertion(LoadedHG =@= HG).

test(round_trip_keeps_every_hg_literal_in_the_precondition,
     [ setup(temp_file_(File)), cleanup(cleanup_(File)) ]) :-
    learned_hook_(VS, Models),
    write_model_file(File, hook, Models, VS),
    loaded_models_(File, hook, [learned_model(hook, Action, Pre, Eff)]),
    assertion(Action-Pre-Eff =@=
              pull_out(T, C, X)-[holding(T), in_tube(C, X), handle_length(T, medium),
                                 hook_side(T, right), behind(T, C), centred_on(T, C),
                                 hook_down(T), in_tube(T, X)]-
              [add(out_of_tube(C, X)), del(in_tube(T, X)), del(in_tube(C, X))]).

test(model_file_is_readable_text, [ setup(temp_file_(File)), cleanup(cleanup_(File)) ]) :-
    short_hook_failed_(VS, Models),
    write_model_file(File, hook, Models, VS),
    read_file_to_string(File, Text, []),
    assertion(sub_string(Text, 0, _, _, "%   Learned by CREATIVE-py, case hook.")),
    assertion(sub_string(Text, _, _, _, "learned_model(hook, pull_out(")).

test(created_variant_is_written_after_the_learned_model,
     [ setup(temp_file_(File)), cleanup(cleanup_(File)) ]) :-
    short_hook_failed_(VS, Models),
    created_models(Models, VS, handle_length(_, medium), handle_length(_, long), Created),
    write_model_file(File, hook, Models, VS, [created(longer_tube, Created)]),
    kb_reset,
    load_model_file(File),
    findall(Task, learned_model(Task, _, _, _), Tasks),
    assertion(Tasks == [hook, hook-longer_tube]),
    learned_model(hook-longer_tube, Action, Pre, Eff),
    assertion(Action-Pre-Eff =@=
              pull_out(T, C, X)-[holding(T), in_tube(C, X), handle_length(T, long),
                                 in_tube(T, X), behind(T, C), centred_on(T, C), hook_down(T)]-
              [add(out_of_tube(C, X)), del(in_tube(T, X)), del(in_tube(C, X))]).

test(missing_file, error(existence_error(source_sink, File))) :-
    File = '/nonexistent/creative-py/model.pl',
    load_model_file(File).

test(syntax_error_names_file_and_line,
     [ setup(temp_file_with_("learned_model(hook, a(X), [], []).\nlearned_model(hook, b(X), [, []).\n",
                             File)),
       cleanup(cleanup_(File)) ]) :-
    kb_reset,
    catch(load_model_file(File), Error, true),
    assertion(Error = error(syntax_error(_), file(File, 2, _, _))),
    assertion(\+ learned_model(hook, _, _, _)).    % nothing half-loaded

test(other_terms_are_refused,
     [ setup(temp_file_with_("foo(1).\n", File)), cleanup(cleanup_(File)),
       error(domain_error(learned_term, foo(1))) ]) :-
    load_model_file(File).

                 /*******************************
                 *     PLANNING WITH THE MODEL  *
                 *******************************/

test(learned_action_models_take_hg_and_hs_pose_as_precondition) :-
    learned_hook_(VS, Models),
    learned_action_models(Models, VS, [Learned]),
    assertion(Learned =@= action_model(pull_out, [T-tool, C-target, X-site],
                                       [holding(T), in_tube(C, X), handle_length(T, medium),
                                        hook_side(T, right), behind(T, C), centred_on(T, C),
                                        hook_down(T), in_tube(T, X)],
                                       [out_of_tube(C, X)],
                                       [in_tube(T, X), in_tube(C, X)])).

test(plan_task_positions_the_tool_before_pulling) :-
    learned_hook_(VS, Models),
    fixture_primitive(hook, P),
    plan_task(hook, Models, VS, P, [], R),
    assertion(R == plan([pick_up(hook_a2), position_tool(hook_a2, cube1, tube1),
                         pull_out(hook_a2, cube1, tube1)])).

test(plan_task_places_the_learned_wedge) :-
    learned_wedge_(VS, Models),
    vs_bounds(VS, _, HG),
    assertion(HG =@= (tool_pose(W, D, _) :- near(W, D), far_from_hinge(W, D),
                                           tip_towards(W, D), shape(W, triangular_prism),
                                           block_length(W, long))),
    fixture_primitive(wedge, P),
    plan_task(wedge, Models, VS, P, [], R),
    assertion(R == plan([pick_up(wedge_a2), place(wedge_a2, door1, floor1),
                         hold_door(wedge_a2, door1, floor1)])).

test(plan_task_without_a_suitable_tool) :-
    learned_hook_(VS, Models),
    fixture_primitive(hook, P0),
    exclude(about_(hook_a2), P0, P1),
    exclude(about_(hook_a4), P1, P),
    plan_task(hook, Models, VS, P, [], R),
    assertion(R = no_plan(no_object_satisfies(pull_out, _))).

test(plan_task_writes_pddl,
     [ setup(( temp_file_(Dom), temp_file_(Prob) )),
       cleanup(( cleanup_(Dom), cleanup_(Prob) )) ]) :-
    learned_hook_(VS, Models),
    fixture_primitive(hook, P),
    plan_task(hook, Models, VS, P, [pddl(Dom, Prob)], R),
    assertion(R = plan([_, _, _])),
    read_file_to_string(Dom, D, []),
    read_file_to_string(Prob, Pr, []),
    assertion(sub_string(D, _, _, _, "pull_out")),
    assertion(sub_string(Pr, _, _, _, "hook_a2")).

about_(Object, Fact) :-
    arg(1, Fact, A),
    A == Object.

test(created_models_swap_the_replaced_literal) :-
    short_hook_failed_(VS, Models),
    created_models(Models, VS, handle_length(_, medium), handle_length(_, long), [M]),
    assertion(M =@= action_model(pull_out, [T-tool, C-target, X-site],
                                 [holding(T), in_tube(C, X), handle_length(T, long),
                                  in_tube(T, X), behind(T, C), centred_on(T, C), hook_down(T)],
                                 [out_of_tube(C, X)], [in_tube(T, X), in_tube(C, X)])).

test(created_models_add_an_instance_hg_did_not_hold) :-
    short_hook_failed_(VS, Models),
    created_models(Models, VS, hook_length(_, long), hook_length(_, short), [M]),
    assertion(M =@= action_model(pull_out, [T-tool, C-target, X-site],
                                 [holding(T), in_tube(C, X), handle_length(T, medium),
                                  in_tube(T, X), behind(T, C), centred_on(T, C), hook_down(T), hook_length(T, short)],
                                 [out_of_tube(C, X)], [in_tube(T, X), in_tube(C, X)])).

test(plan_with_created_models_needs_the_created_tool) :-
    short_hook_failed_(VS, Models),
    created_models(Models, VS, handle_length(_, medium), handle_length(_, long), Created),
    fixture_primitive(hook, P),
    observed_state(hook, P, State),
    innate_action_models(hook, Innate),
    append(Created, Innate, All),
    action_task_goal(hook, Goal),
    plan(State, Goal, All, [], R),
    assertion(R = plan([pick_up(T), position_tool(T, cube1, tube1),
                        pull_out(T, cube1, tube1)])),
    assertion(memberchk(T, [hook_a3, hook_a5])).

test(plan_models_plans_with_the_created_models_and_writes_their_pddl,
     [ setup(( temp_file_(Dom), temp_file_(Prob) )),
       cleanup(( cleanup_(Dom), cleanup_(Prob) )) ]) :-
    short_hook_failed_(VS, Models),
    created_models(Models, VS, handle_length(_, medium), handle_length(_, long), Created),
    fixture_primitive(hook, P),
    plan_models(hook, Created, P, [pddl(Dom, Prob), domain_name(creative_long),
                                   problem_name(task_long)], R),
    assertion(R = plan([pick_up(T), position_tool(T, cube1, tube1),
                        pull_out(T, cube1, tube1)])),
    assertion(memberchk(T, [hook_a3, hook_a5])),
    read_file_to_string(Dom, D, []),
    read_file_to_string(Prob, Pr, []),
    assertion(sub_string(D, _, _, _, "(define (domain creative_long)")),
    assertion(sub_string(D, _, _, _, "(handle_length ?tool long)")),
    assertion(sub_string(Pr, _, _, _, "(define (problem task_long)")),
    % The created model's precondition names no class literal, yet every catalogued
    % object is a tool of the PDDL problem.
    assertion(\+ sub_string(D, _, _, _, "(tool ")),
    observed_state(hook, P, State),
    forall(( member(L, State), L = tool(O) ),
           ( format(string(S), "~w - tool_object", [O]),
             assertion(sub_string(Pr, _, _, _, S)) )).

:- end_tests(model_file).
