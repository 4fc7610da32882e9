:- begin_tests(pddl).

:- use_module(library(lists)).
:- use_module(library(readutil)).
:- use_module('fixtures/demonstrations').

models_(Case, Models) :-
    fixture_demonstration(Case, Steps),
    innate_action_models(Case, Innate),
    observe_demonstration(Steps, Innate, models(_, New, _)),
    append(New, Innate, Models).

contains_(Text, Sub) :-
    once(sub_string(Text, _, _, _, Sub)).

test(hook_domain_strips) :-
    models_(hook, Models),
    pddl_domain(hook, Models, Text),
    contains_(Text, "(:requirements :strips :typing)\n"),
    contains_(Text, "(:constants long medium right thick wide - value)"),
    contains_(Text, "(:action position_tool\n    :parameters (?tool - tool_object ?target - target ?site - site)\n    :precondition (and (holding ?tool) (in_tube ?target ?site))\n    :effect (and (in_tube ?tool ?site) (behind ?tool ?target) (centred_on ?tool ?target) (hook_down ?tool)))"),
    contains_(Text, ":effect (and (out_of_tube ?target ?site) (not (in_tube ?tool ?site)) (not (in_tube ?target ?site))))").

test(wedge_domain_renames_object) :-
    models_(wedge, Models),
    pddl_domain(wedge, Models, Text),
    contains_(Text, "(is_object ?a1 - object)"),
    contains_(Text, "(is_object ?tool)"),
    \+ contains_(Text, "(object ").

test(negative_preconditions_declared) :-
    pddl_domain(d, [action_model(a, [X-tool], [p(X), not(q(X))], [q(X)], [])], Text),
    contains_(Text, "(:requirements :strips :typing :negative-preconditions)"),
    contains_(Text, ":precondition (and (p ?tool) (not (q ?tool)))").

test(extra_predicates_declared) :-
    pddl_domain(d, [], [extra_literals([door_held(door1), gripper_empty])], Text),
    contains_(Text, "(door_held ?a1 - object)"),
    contains_(Text, "(gripper_empty)").

test(bad_name, error(domain_error(pddl_name, 'Bad'))) :-
    pddl_domain('Bad', [], _).

test(not_strips, error(domain_error(pddl_strips_literal(a), p('?tool', _)))) :-
    pddl_domain(d, [action_model(a, [X-tool], [p(X, _)], [], [])], _).

test(problem_text, Text == "(define (problem p)\n  (:domain d)\n  (:objects h - tool_object c - target)\n  (:init\n    (on_table h)\n    (gripper_empty)\n  )\n  (:goal (and (holding h) (near h c)))\n)\n") :-
    pddl_problem(p, d, [h-tool, c-target], [on_table(h), gripper_empty],
                 [holding(h), near(h, c)], Text).

test(problem_bad_object, error(domain_error(typed_object, h-robot))) :-
    pddl_problem(p, d, [h-robot], [], [], _).

test(plan_text, Text == "(pick_up hook_a2)\n(place wedge_a2 door1 floor1)\n") :-
    pddl_plan([pick_up(hook_a2), place(wedge_a2, door1, floor1)], Text).

test(write_files, [setup(tmp_files_(D, P)), cleanup(delete_files_([D, P]))]) :-
    models_(hook, Models),
    fixture_initial_state(hook, S0),
    pddl_write_files(D, P, Models, S0, [out_of_tube(cube1, tube1)],
                     [domain_name(hook), problem_name(pull_cube)]),
    read_file_to_string(D, DText, []),
    read_file_to_string(P, PText, []),
    contains_(DText, "(define (domain hook)"),
    contains_(PText, "(define (problem pull_cube)\n  (:domain hook)"),
    contains_(PText, "(:objects cube1 - target hook_a1 - tool_object"),
    contains_(PText, "left - value short - value tube1 - site)"),
    \+ contains_(PText, "medium - value"),
    \+ contains_(PText, "(stick "),
    contains_(PText, "(:goal (and (out_of_tube cube1 tube1)))").

tmp_files_(D, P) :-
    tmp_file(domain, D),
    tmp_file(problem, P).

delete_files_(Files) :-
    forall(( member(F, Files), exists_file(F) ), delete_file(F)).

%   The models of a demonstration whose preconditions lost the class literals (tool/1,
%   hook_like/1, object/1, block/1), as a learned h_g usually does.
models_without_class_literals_(Case, Models) :-
    models_(Case, Models0),
    maplist(drop_class_literals_, Models0, Models).

drop_class_literals_(action_model(N, Ps, Pre0, Add, Del), action_model(N, Ps, Pre, Add, Del)) :-
    exclude(class_literal_, Pre0, Pre).

class_literal_(L) :-
    compound(L),
    compound_name_arguments(L, F, [_]),
    memberchk(F, [tool, hook_like, object, block]).

write_texts_(Case, Models, State, Options, DText, PText) :-
    tmp_files_(D, P),
    action_task_goal(Case, Goal),
    call_cleanup(( pddl_write_files(D, P, Models, State, Goal, Options),
                   read_file_to_string(D, DText, []),
                   read_file_to_string(P, PText, []) ),
                 delete_files_([D, P])).

test(tools_typed_from_the_ontology_whatever_h_g_holds) :-
    models_without_class_literals_(hook, Models),
    fixture_initial_state(hook, S0),
    write_texts_(hook, Models, S0, [case(hook)], DText, PText),
    \+ contains_(DText, "(tool "),
    \+ contains_(DText, "(hook_like "),
    forall(member(T, [hook_a1, hook_a2, hook_a3, hook_a4, hook_a5]),
           ( format(string(S), "~w - tool_object", [T]), contains_(PText, S) )),
    \+ contains_(PText, "hook_a2 - value"),
    contains_(PText, "cube1 - target"),
    contains_(PText, "tube1 - site").

test(tools_typed_from_the_catalogue_without_the_case_option) :-
    models_without_class_literals_(hook, Models),
    fixture_initial_state(hook, S0),
    write_texts_(hook, Models, S0, [], _, PText),
    contains_(PText, "hook_a2 - tool_object"),
    contains_(PText, "hook_a5 - tool_object").

test(a_subclass_literal_makes_a_tool_of_the_case) :-
    models_without_class_literals_(hook, Models),
    fixture_initial_state(hook, S0),
    exclude(class_literal_, S0, S1),
    write_texts_(hook, Models, S1, [case(hook)], _, PText),
    contains_(PText, "hook_a2 - tool_object"),
    contains_(PText, "hook_a5 - tool_object").

test(blocks_typed_as_tools) :-
    models_without_class_literals_(wedge, Models),
    fixture_initial_state(wedge, S0),
    exclude([L]>>(L = object(_)), S0, S1),
    write_texts_(wedge, Models, S1, [case(wedge), objects([floor1-site])], _, PText),
    forall(member(W, [box_a1, cylinder_b1, wedge_a1, wedge_a2]),
           ( format(string(S), "~w - tool_object", [W]), contains_(PText, S) )),
    contains_(PText, "door1 - target"),
    contains_(PText, "floor1 - site").

test(case_tool_objects, Tools == [h1, s1, w9]) :-
    case_tool_objects(hook, [hook(h1), stick(s1), tool(w9), in_tube(cube1, tube1),
                             handle_length(h1, medium), on_table(x7)], Tools).

test(case_tool_objects_unknown_case, error(existence_error(case, kitchen))) :-
    case_tool_objects(kitchen, [], _).

:- end_tests(pddl).
