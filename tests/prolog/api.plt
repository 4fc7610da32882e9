:- begin_tests(api).

:- use_module(library(plunit)).
:- use_module(library(lists)).
:- use_module(library(http/json), [json_read/2]).
:- use_module('../../prolog/api').

test(ping_is_ok_pong, Reply == ok(pong)) :-
    api_call(ping, Reply).

test(failure_is_the_atom_failed, Reply == failed) :-
    api_call(theta_subsumes(p(a), p(b)), Reply).

test(unknown_operation_is_a_ground_existence_error) :-
    api_call(no_such_op(1), Reply),
    assertion(ground(Reply)),
    assertion(Reply = error(error(existence_error(api_operation, no_such_op/1), _))).

test(new_variables_are_named_G0_G1, Reply == ok(f('$VAR'('_G0'), b, '$VAR'('_G0')))) :-
    api_call(term_lgg(f(a, b, a), f(c, b, c)), Reply).

test(reply_is_ground_even_with_anonymous_variables) :-
    api_call(echo(f(_, X, X, _)), Reply),
    assertion(ground(Reply)),
    Reply = ok(f(A, B, C, D)),
    assertion(B == C),
    assertion(A \== B),
    assertion(A \== D).

test(request_variable_names_survive_the_round_trip,
     Json == "{\"f\":\"ok\",\"a\":[{\"f\":\"f\",\"a\":[{\"v\":\"X\"},{\"v\":\"_G0\"},{\"v\":\"X\"}]}]}") :-
    api_request("echo(f(X, _, X))", Json).

test(fresh_names_skip_names_the_request_uses,
     Json == "{\"f\":\"ok\",\"a\":[{\"f\":\"f\",\"a\":[{\"v\":\"_G0\"},{\"v\":\"_G1\"}]}]}") :-
    api_request("echo(f(_G0, _))", Json).

test(json_escapes_quotes_backslashes_and_control_characters,
     Json == "{\"f\":\"ok\",\"a\":[[\"a\\\"b\\\\c\\n\",{\"s\":\"s\\u0000\"},\"[]\",[]]]}") :-
    api_request("echo(['a\"b\\\\c\\n', \"s\\x0\\\", '[]', []])", Json).

test(control_characters_and_nul_are_escaped) :-
    atom_codes(A, [0'x, 0, 0'y, 1, 0'z, 31, 0'", 0'\\, 127, 0'é]),
    string_codes(Str, [0'n, 0]),
    with_output_to(string(S), api:api_write_json_([A, Str, plain])),
    assertion(sub_string(S, _, _, _, "x\\u0000y\\u0001z")),
    assertion(sub_string(S, _, _, _, "n\\u0000")),
    open_string(S, In),
    json_read(In, Back),
    assertion(Back = [AText, json([s=StrText]), plain]),
    atom_string(A, AText0),
    assertion(atom_string(AText, AText0)),
    assertion(atom_string(StrText, Str)).

test(special_floats_written_as_json_literals,
     S == "[NaN,Infinity,-Infinity,-1.5e-300,2,\"a\"]") :-
    NaN is nan,
    Inf is inf,
    NInf is -inf,
    with_output_to(string(S), api:api_write_json_([NaN, Inf, NInf, -1.5e-300, 2, a])).

test(request_that_does_not_parse_is_a_syntax_error_reply) :-
    api_request("f(", Json),
    assertion(sub_string(Json, 0, _, _, "{\"f\":\"error\"")),
    assertion(sub_string(Json, _, _, _, "syntax_error")).

test(non_text_request_is_a_type_error_reply) :-
    api_request(f(x), Json),
    assertion(sub_string(Json, _, _, _, "type_error")).

test(variant_is_structural_equality_up_to_renaming) :-
    api_call(variant(p(X, Y, X), p(A, _, A)), R1),
    assertion(R1 == ok(true)),
    api_call(variant(p(X, Y), p(Z, Z)), R2),
    assertion(R2 == failed).

test(parse_keeps_variable_names, Reply == ok((p('$VAR'('X')) :- q('$VAR'('X'), "s")))) :-
    api_call(parse("p(X) :- q(X, \"s\")"), Reply).

test(case_info_for_a_manifest,
     Reply == ok(case([pick_up, place, release_door], [door_held(door1)], door1, floor1,
                      wedge_pose))) :-
    api_call(case_info(wedge), Reply).

test(case_info_of_an_unknown_case_is_an_error) :-
    api_call(case_info(kitchen), Reply),
    assertion(Reply = error(error(existence_error(case, kitchen), _))).

test(pose_target_gives_the_world_target, Reply == ok(tip(0.9400000000000001, -0.25, 0.0))) :-
    api_call(pose_target(hook, h, [pose(cube1, 0.9, -0.25, -0.0125, 0.0)],
                         hook_pose(0.04, 0.0, 0.0)),
             Reply).

test(every_dispatched_goal_is_defined) :-
    forall(clause(api:api_op(Request, _, Goal), true),
           (   functor(Goal, Name, Arity),
               (   predicate_property(api:Goal, defined)
               ->  true
               ;   memberchk(Name/Arity, [true/0, (=@=)/2, findall/3])
               )
           ->  true
           ;   format(user_error, "undefined goal for ~q~n", [Request]),
               fail
           )).

test(operations_are_listed_once_each) :-
    findall(Op, api_operation(Op), Ops),
    msort(Ops, Sorted),
    sort(Ops, Unique),
    assertion(Sorted == Unique),
    assertion(memberchk(clause_lgg/2, Ops)),
    assertion(memberchk(vs_update/2, Ops)).

test(consult_reports_syntax_errors_with_file_and_line,
     [ setup(api_test_file_("ok_fact(1).\nbad(X :- .\nok_fact(2).\n", File)),
       cleanup(delete_file(File))
     ]) :-
    api_call(consult(File), Reply),
    Reply = ok(load_report(Path, Errors, Warnings)),
    assertion(Warnings == []),
    assertion(Errors = [message(syntax_error, Path, 2, _)]).

test(consult_of_a_missing_file_is_an_existence_error) :-
    api_call(consult('/nonexistent/creative_api_test.pl'), Reply),
    assertion(Reply = error(error(existence_error(source_sink, _), _))).

test(load_status_counts_printed_messages) :-
    api_call(load_status, Reply),
    Reply = ok(status(E, W)),
    assertion(integer(E)),
    assertion(integer(W)).

api_test_file_(Text, File) :-
    tmp_file_stream(text, File0, Stream),
    close(Stream),
    file_name_extension(File0, pl, File),
    setup_call_cleanup(open(File, write, Out), write(Out, Text), close(Out)),
    delete_file(File0).

:- end_tests(api).
