:- module(api,
          [ api_request/2,              % +RequestText, -ReplyJson
            api_call/2,                 % +Request, -Reply
            api_operation/1             % ?NameArity
          ]).

/** <module> The facade: the one entry point Python calls through the bridge

Python (`creative_py/bridge/`) calls exactly one predicate, api_request/2, with a
constant query shape: the varying request travels as a string argument that this
module parses, so pyswip never sees a new query text. Each operation is one row of the
table api_op/3, deterministic, and answers exactly one ground reply term:

    ok(Result)     the operation's goal succeeded (first solution; operations that
                   want every answer collect them with findall/3 in their goal)
    failed         the goal has no solution ("no")
    error(E)       the goal raised E (a request that does not parse, or names no
                   operation, raises too)

Variables in a reply are bound to '$VAR'(Name): a variable of the request keeps its
name, a new one is named '_G0', '_G1', ... (skipping names the request uses), so
clauses with variables travel back and forth with stable names. The reply is written
as JSON for the Python decoder (creative_py/bridge/codec.py describes the schema):
atoms as JSON strings, proper lists as arrays, numbers as numbers, strings as
{"s":Text}, variables as {"v":Name}, compounds as {"f":Name,"a":Args}, right-nested chains of one binary functor (clause
bodies) flat as {"r":Name,"a":Items}, blobs and dicts
(e.g. the stack_overflow{...} context of a resource error) as {"b":Text}, their
printed form.

To add an operation, add ONE row to api_op/3 (request term, result term, goal) and,
if it needs a new module, its use_module/1 below.

*/

:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(http/json), [json_write/3]).

:- use_module(knowledge, [load_ontology/1, load_default_ontology/0]).
:- use_module(lgg, [term_lgg/3, clause_lgg/3]).
:- use_module(subsumption,
              [ theta_subsumes/2, theta_subsumes/3, clause_reduce/2, clause_reduce/3,
                clause_covers/2, clause_violations/3, clause_violations/4 ]).
:- use_module(geometry_clp, [solve_pose/5, solve_size/5, pose_reachable/5]).
:- use_module(rlgg, [rlgg/4, rlgg/5, saturate/4]).
:- use_module(nbr, [nbr_reduce/3]).
:- use_module(version_space,
              [ vs_init/2, vs_update/3, vs_bounds/3, vs_unknown/2, vs_examples/3,
                vs_converged/1, vs_covers/3, vs_notes/2, vs_count/3,
                vs_init_prior/3, vs_prior/3, vs_prior_events/2 ]).
:- use_module(text_terms, [text_term/3]).
:- use_module(transfer, [read_prior/2, read_prior_text/3, prior_shared/3, prior_literals/4,
                          prior_contradicted/4, prior_kinds/3]).
:- use_module(replacement, [replacement/3]).
:- use_module(abstract_state, [abstract_state/3, pose_numbers/4, pose_world/5]).
:- use_module(case, [case_info/2, tool_vocabulary/2, size_context_facts/1,
                      catalogue_predicates/2, case_missing_hooks/2,
                      catalogue_ranges/3]).
:- use_module(experiment, [learn_from_demonstration/3, observed_state/3,
                           plan_experiment/4, plan_experiment/5, plan_experiment/6,
                           plan_use/5,
                           label_trial/7, experiment_strategies/1]).
:- use_module(strategy, []).        % the experiment strategies (experiment's hooks)
:- use_module(creation, [next_tool/6, creation_candidates/3, catalogue_first/5]).
:- use_module(model_file, [write_model_file/4, load_model_file/1, plan_task/6,
                            plan_models/5, created_models/5, write_model_file/5]).
:- use_module(planner, [plan/5]).
:- use_module(action_model, [innate_action_models/2]).
:- use_module(pddl, [pddl_write_files/6]).

%!  api_op(?Request, -Result, -Goal) is nondet.
%
%   The operation table: Request is the term Python sends, Goal is called once, and
%   Result (bound by Goal) is the answer inside ok(Result).

% The bridge itself.
api_op(ping, pong, true).
api_op(version, version(api(Api), swipl(Major, Minor, Patch)),
       api_version_(Api, Major, Minor, Patch)).
api_op(operations, Ops, findall(Op, api_operation(Op), Ops)).
api_op(echo(Term), Term, true).
api_op(variant(A, B), true, A =@= B).
api_op(parse(Text), Term, api_parse_(Text, Term)).
api_op(consult(File), Report, api_consult_(File, Report)).
api_op(load_status, status(Errors, Warnings), api_load_status_(Errors, Warnings)).
api_op(timed(Request, N), Seconds, api_timed_(Request, N, Seconds)).
% Knowledge.
api_op(load_ontology(Spec), true, load_ontology(Spec)).
api_op(load_default_ontology, true, load_default_ontology).
% Generalisation and subsumption (lgg.pl, subsumption.pl).
api_op(term_lgg(T1, T2), G, term_lgg(T1, T2, G)).
api_op(clause_lgg(C1, C2), G, clause_lgg(C1, C2, G)).
api_op(theta_subsumes(G, S), true, theta_subsumes(G, S)).
api_op(theta_subsumes(G, S, Options), true, theta_subsumes(G, S, Options)).
api_op(clause_reduce(C), R, clause_reduce(C, R)).
api_op(clause_reduce(C, Options), R, clause_reduce(C, R, Options)).
api_op(clause_covers(C, E), true, clause_covers(C, E)).
api_op(clause_violations(C, E), V, clause_violations(C, E, V)).
api_op(clause_violations(C, E, Options), V, clause_violations(C, E, V, Options)).
api_op(rlgg(E1, E2, BK), C, rlgg(E1, E2, BK, C)).
api_op(rlgg(E1, E2, BK, Options), C, rlgg(E1, E2, BK, C, Options)).
api_op(saturate(E, BK, Options), C, saturate(E, BK, C, Options)).
api_op(nbr_reduce(C, Negatives), R, nbr_reduce(C, Negatives, R)).
% The version space (version_space.pl); VS is an opaque term Python hands back.
api_op(vs_init(Example), VS, vs_init(Example, VS)).
api_op(vs_update(VS0, Labelled), VS, vs_update(VS0, Labelled, VS)).
api_op(vs_bounds(VS), bounds(HS, HG), vs_bounds(VS, HS, HG)).
api_op(vs_unknown(VS), Literals, vs_unknown(VS, Literals)).
api_op(vs_examples(VS), examples(Pos, Neg), vs_examples(VS, Pos, Neg)).
api_op(vs_converged(VS), true, vs_converged(VS)).
api_op(vs_covers(VS, Bound, Example), true, vs_covers(VS, Bound, Example)).
api_op(vs_notes(VS), Notes, vs_notes(VS, Notes)).
api_op(vs_count(VS), count(N, Exact), vs_count(VS, N, Exact)).
% Transfer from a prior case's learned model (transfer.pl).
api_op(vs_init_prior(Case, Example, Lits), VS,
       ( prior_kinds(Case, Lits, Kinded), vs_init_prior(Example, Kinded, VS) )).
api_op(vs_prior(VS), prior(Kept, Dropped), vs_prior(VS, Kept, Dropped)).
api_op(vs_prior_events(VS), Events, vs_prior_events(VS, Events)).
api_op(read_prior(File), Prior, read_prior(File, Prior)).
api_op(read_prior_text(Text, File), Prior, read_prior_text(Text, File, Prior)).
api_op(prior_shared(Case, Prior), Shared, prior_shared(Case, Prior, Shared)).
api_op(prior_literals(Case, Prior, Example), Lits, prior_literals(Case, Prior, Example, Lits)).
api_op(prior_contradicted(Case, Prior, Example), Lits,
       prior_contradicted(Case, Prior, Example, Lits)).
% Tool creation (replacement.pl) and perception's facts -> literals (abstract_state.pl).
api_op(replacement(Literal), replacement(General, Alternatives),
       replacement(Literal, General, Alternatives)).
api_op(abstract_state(Case, Facts), Abstract, abstract_state(Case, Facts, Abstract)).
api_op(pose_numbers(Case, Tool, Facts), Pose, pose_numbers(Case, Tool, Facts, Pose)).
api_op(pose_target(Case, Tool, Facts, Pose), World, pose_world(Case, Tool, Facts, Pose, World)).
% The case as the ontology describes it (case.pl), for checking a manifest.
api_op(case_info(Case), Info, case_info(Case, Info)).
api_op(tool_vocabulary(Case), Classes, tool_vocabulary(Case, Classes)).
api_op(size_context_facts, Indicators, size_context_facts(Indicators)).
api_op(size_context_facts(Case), Indicators, size_context_facts(Case, Indicators)).
api_op(catalogue_predicates(Case), Indicators, catalogue_predicates(Case, Indicators)).
api_op(case_missing_hooks(Case), Missing, case_missing_hooks(Case, Missing)).
api_op(catalogue_ranges(Case, Facts), Ranges, catalogue_ranges(Case, Facts, Ranges)).
% Geometry: spatial literals -> pose numbers, structural literals -> dimensions.
api_op(solve_pose(Case, Required, Negated, Context), R,
       solve_pose(Case, Required, Negated, Context, R)).
api_op(solve_size(Case, Kind, Literals, Context), R,
       solve_size(Case, Kind, Literals, Context, R)).
api_op(pose_reachable(Case, Tool, Required, Context), R,
       pose_reachable(Case, Tool, Required, Context, R)).
% Tool-use learning (Algorithm 1) and tool creation (Algorithm 2).
api_op(learn_from_demonstration(Case, Steps), R, learn_from_demonstration(Case, Steps, R)).
api_op(observed_state(Case, Facts), S, observed_state(Case, Facts, S)).
api_op(next_experiment(Case, VS, Facts), R, plan_experiment(Case, VS, Facts, R)).
api_op(next_experiment(Case, VS, Facts, Skip), R, plan_experiment(Case, VS, Facts, Skip, R)).
api_op(next_experiment(Case, VS, Facts, Skip, Options), R,
       plan_experiment(Case, VS, Facts, Skip, Options, R)).
api_op(experiment_strategies, Templates, experiment_strategies(Templates)).
api_op(created_models(Models, VS, Replaced, Instance), Ms,
       created_models(Models, VS, Replaced, Instance, Ms)).
api_op(plan_use(Case, VS, Facts, Options), R, plan_use(Case, VS, Facts, Options, R)).
api_op(label_trial(Case, VS0, Experiment, Facts, Label, Mode), VS,
       label_trial(Case, VS0, Experiment, Facts, Label, Mode, VS)).
api_op(next_tool(Case, VS, Tried, Context), R, next_tool(Case, VS, Tried, Context, [], R)).
api_op(creation_candidates(VS), Cs, creation_candidates(VS, [], Cs)).
api_op(catalogue_first(Case, VS, Facts, Exclude), R,
       catalogue_first(Case, VS, Facts, Exclude, R)).
api_op(write_model_file(File, Case, Models, VS, Created), true,
       write_model_file(File, Case, Models, VS, Created)).
api_op(write_model_file(File, Case, Models, VS), true,
       write_model_file(File, Case, Models, VS)).
api_op(load_model_file(File), true, load_model_file(File)).
api_op(plan_task(Case, Models, VS, Facts, Options), R,
       plan_task(Case, Models, VS, Facts, Options, R)).
api_op(plan_models(Case, Learned, Facts, Options), R,
       plan_models(Case, Learned, Facts, Options, R)).
api_op(plan(State, Goal, Models, Options), R, plan(State, Goal, Models, Options, R)).
api_op(innate_action_models(Case), Ms, innate_action_models(Case, Ms)).
api_op(pddl_write_files(Dom, Prob, Models, State, Goal, Options), true,
       pddl_write_files(Dom, Prob, Models, State, Goal, Options)).

%!  api_operation(?NameArity) is nondet.
%
%   NameArity is Name/Arity of an operation the facade dispatches.
%
%   ==
%   ?- api_operation(ping/0).
%   true.
%   ==

api_operation(Name/Arity) :-
    clause(api_op(Request, _, _), _),
    functor(Request, Name, Arity).

%!  api_request(+RequestText, -ReplyJson) is det.
%
%   Parse RequestText (a string or atom holding one Prolog term, no full stop), run
%   the operation it names with api_call/2 and unify ReplyJson with the JSON text of
%   the reply. A request that does not parse answers error(syntax_error(...)); this
%   predicate itself never fails and never raises.
%
%   ==
%   ?- api_request("term_lgg(f(a,b),f(c,b))", R).
%   R = "{\"f\":\"ok\",\"a\":[{\"f\":\"f\",\"a\":[{\"v\":\"_G0\"},\"b\"]}]}".
%   ==

api_request(Text, ReplyJson) :-
    catch(api_parse_request_(Text, Request, Bindings), Error, true),
    (   var(Error)
    ->  api_call_(Request, Bindings, Reply)
    ;   api_ground_reply_([], error(Error), Reply)
    ),
    api_reply_json_(Reply, ReplyJson).

api_parse_request_(Text, Request, Bindings) :-
    must_be(text, Text),
    term_string(Request, Text, [variable_names(Bindings)]).

%!  api_call(+Request, -Reply) is det.
%
%   Run the operation Request from the table and unify Reply with ok(Result),
%   failed or error(E), made ground as described in the module header. This is the
%   term-level entry (for Prolog callers and tests); Python uses api_request/2.
%
%   ==
%   ?- api_call(term_lgg(f(a, b), f(c, b)), R).
%   R = ok(f('$VAR'('_G0'), b)).
%   ?- api_call(no_such_op, R).
%   R = error(error(existence_error(api_operation, no_such_op/0), _)).   % made ground
%   ==

api_call(Request, Reply) :-
    api_call_(Request, [], Reply).

api_call_(Request, Bindings, Reply) :-
    catch(api_run_(Request, Reply0), Error, Reply0 = error(Error)),
    api_ground_reply_(Bindings, Reply0, Reply).

api_run_(Request, Reply) :-
    (   var(Request)
    ->  instantiation_error(Request)
    ;   api_op(Request, Result, Goal)
    ->  (   call(Goal)
        ->  Reply = ok(Result)
        ;   Reply = failed
        )
    ;   callable(Request)
    ->  functor(Request, Name, Arity),
        existence_error(api_operation, Name/Arity)
    ;   type_error(callable, Request)
    ).

%   api_ground_reply_(+Bindings, +Reply0, -Reply) is det.
%
%   Copy Reply0 without attributes (constraints are not data) and bind its variables
%   to '$VAR'(Name): request variables keep their names, new ones get '_G<N>'.

api_ground_reply_(Bindings, Reply0, Reply) :-
    copy_term(Bindings-Reply0, Bindings1-Reply1, _Constraints),
    (   acyclic_term(Reply1)
    ->  Reply2 = Reply1
    ;   Reply2 = error(error(type_error(acyclic_term, reply), _))
    ),
    foldl(api_bind_name_, Bindings1, [], Used),
    term_variables(Reply2, Fresh),
    api_name_fresh_(Fresh, Used, 0),
    Reply = Reply2.

api_bind_name_(Name = Var, Used, [Name|Used]) :-
    (   var(Var)
    ->  Var = '$VAR'(Name)
    ;   true
    ).

api_name_fresh_([], _, _).
api_name_fresh_([Var|Vars], Used, N0) :-
    api_fresh_name_(Used, N0, Name, N),
    Var = '$VAR'(Name),
    api_name_fresh_(Vars, Used, N).

api_fresh_name_(Used, N0, Name, N) :-
    format(atom(Name0), '_G~d', [N0]),
    N1 is N0 + 1,
    (   memberchk(Name0, Used)
    ->  api_fresh_name_(Used, N1, Name, N)
    ;   Name = Name0,
        N = N1
    ).

%   api_reply_json_(+Reply, -Json) is det.

api_reply_json_(Reply, Json) :-
    catch(with_output_to(string(Json), api_write_json_(Reply)), Error, true),
    (   var(Error)
    ->  true
    ;   format(string(Text), "~q", [Error]),
        with_output_to(string(Json),
                       api_write_json_(error(error(api_reply_unwritable(Text), _))))
    ).

api_write_json_(T) :-
    (   var(T)
    ->  write('{"v":"_"}')
    ;   T == []
    ->  write('[]')
    ;   is_list(T)
    ->  write('['),
        api_write_json_items_(T),
        write(']')
    ;   string(T)
    ->  write('{"s":'),
        api_write_json_text_(T),
        write('}')
    ;   atom(T)
    ->  api_write_json_text_(T)
    ;   integer(T)
    ->  write(T)
    ;   float(T)
    ->  api_write_json_float_(T)
    ;   rational(T, Num, Den)
    ->  api_write_json_(rdiv(Num, Den))
    ;   ( blob(T, _) ; is_dict(T) )
    ->  format(string(Text), "~q", [T]),
        write('{"b":'),
        api_write_json_text_(Text),
        write('}')
    ;   T = '$VAR'(Name),
        api_variable_name_(Name)
    ->  write('{"v":'),
        api_write_json_text_(Name),
        write('}')
    ;   T = '$VAR'(N),
        integer(N)
    ->  format(string(Name), "~W", [T, [numbervars(true)]]),
        write('{"v":'),
        api_write_json_text_(Name),
        write('}')
    ;   compound_name_arity(T, Name, 2),
        arg(2, T, Right),
        compound(Right),
        compound_name_arity(Right, Name, 2)
    ->  api_binary_chain_(T, Name, Items),
        write('{"r":'),
        api_write_json_text_(Name),
        write(',"a":['),
        api_write_json_items_(Items),
        write(']}')
    ;   compound_name_arguments(T, Name, Args),
        write('{"f":'),
        api_write_json_text_(Name),
        write(',"a":['),
        api_write_json_items_(Args),
        write(']}')
    ).

%   api_binary_chain_(+Term, +Name, -Items) is det.
%
%   Items are the links of the right-nested chain Name(I1, Name(I2, ... In)): a long
%   clause body travels as one flat JSON array instead of a deep nest.

api_binary_chain_(T, Name, [Left|Items]) :-
    arg(1, T, Left),
    arg(2, T, Right),
    (   compound(Right),
        compound_name_arity(Right, Name, 2)
    ->  api_binary_chain_(Right, Name, Items)
    ;   Items = [Right]
    ).

%   api_variable_name_(+Name) is semidet.
%
%   Name is an atom that reads as a variable name the Python side accepts: an ASCII
%   capital or `_`, then ASCII letters, digits or `_`.

api_variable_name_(Name) :-
    atom(Name),
    atom_codes(Name, [C|Cs]),
    (   C =:= 0'_
    ->  true
    ;   C >= 0'A,
        C =< 0'Z
    ),
    forall(member(D, Cs), api_ascii_csym_(D)).

api_ascii_csym_(C) :-
    (   C =:= 0'_
    ->  true
    ;   C >= 0'a, C =< 0'z
    ->  true
    ;   C >= 0'A, C =< 0'Z
    ->  true
    ;   C >= 0'0, C =< 0'9
    ).

api_write_json_items_([]).
api_write_json_items_([X|Xs]) :-
    api_write_json_(X),
    (   Xs == []
    ->  true
    ;   write(','),
        api_write_json_items_(Xs)
    ).

api_write_json_text_(Text) :-
    api_json_specials_(Specials),
    (   split_string(Text, Specials, "", [_]),
        \+ sub_string(Text, _, _, _, "\x0\")
    ->  put_char('"'),
        write(Text),
        put_char('"')
    ;   atom_string(Text, String),
        json_write(current_output, String, [width(0)])
    ).

%   api_json_specials_(-Chars) is det.
%
%   The characters a JSON string must escape: the quote, the backslash and the
%   control characters but NUL (split_string/4 reads its separators as a C string;
%   NUL is checked apart). Text without them is written as it is (the fast path).

api_json_specials_("\"\\\x1\\x2\\x3\\x4\\x5\\x6\\x7\\x8\\x9\\xa\\xb\\xc\\xd\\xe\\xf\\x10\\x11\\x12\\x13\\x14\\x15\\x16\\x17\\x18\\x19\\x1a\\x1b\\x1c\\x1d\\x1e\\x1f\").

api_write_json_float_(F) :-
    float_class(F, Class),
    (   Class == nan
    ->  write('NaN')
    ;   Class == infinite
    ->  (   F > 0
        ->  write('Infinity')
        ;   write('-Infinity')
        )
    ;   format('~w', [F])
    ).

%   api_version_(-Api, -Major, -Minor, -Patch) is det.

api_version_(1, Major, Minor, Patch) :-
    current_prolog_flag(version, V),
    Major is V // 10000,
    Minor is (V // 100) mod 100,
    Patch is V mod 100.

%   api_parse_(+Text, -Term) is det.
%
%   Read Text (one term, no full stop) keeping its variable names; a term nested
%   deeper than text_terms:term_depth_max/1 raises (text_terms.pl says why).

api_parse_(Text, Term) :-
    text_term(Text, Term, Bindings),
    maplist(api_bind_var_name_, Bindings).

api_bind_var_name_(Name = '$VAR'(Name)).

%   api_timed_(+Request, +N, -Seconds) is det.
%
%   Run the operation Request N times inside Prolog (each run's bindings undone) and
%   give the mean wall time per run in seconds: the cost without the bridge.

api_timed_(Request, N, Seconds) :-
    must_be(positive_integer, N),
    (   api_op(Request, _, Goal)
    ->  true
    ;   functor(Request, Name, Arity),
        existence_error(api_operation, Name/Arity)
    ),
    get_time(T0),
    forall(between(1, N, _), \+ \+ once(Goal)),
    get_time(T1),
    Seconds is (T1 - T0) / N.

%   api_load_status_(-Errors, -Warnings) is det.
%
%   The numbers of error and warning messages printed since Prolog started.

api_load_status_(Errors, Warnings) :-
    statistics(errors, Errors),
    statistics(warnings, Warnings).

		 /*******************************
		 *            CONSULT            *
		 *******************************/

%   api_consult_(+File, -Report) is det.
%
%   Load File (an existing file, else existence_error(source_sink, File)) into
%   module user, capturing the errors and warnings printed while loading instead
%   of printing them. Report is load_report(Path, Errors, Warnings), each a list of
%   message(Kind, File, Line, Text), Kind one of syntax_error, error, warning and
%   Line an integer or none. A load that throws runs nodebug/0 (a failed load can
%   leave the debugger on) and passes the exception on.

:- thread_local api_capturing_/0.
:- thread_local api_load_message_/4.

api_consult_(File, load_report(Path, Errors, Warnings)) :-
    must_be(text, File),
    atom_string(FileAtom, File),
    (   absolute_file_name(FileAtom, Path,
                           [access(read), file_type(prolog), file_errors(fail)]),
        exists_file(Path)
    ->  true
    ;   existence_error(source_sink, File)
    ),
    catch(setup_call_cleanup(api_capture_begin_,
                             api_load_and_collect_(Path, Messages),
                             api_capture_end_),
          Error,
          ( nodebug, throw(Error) )),
    partition(api_is_warning_, Messages, Warnings, Errors).

api_load_and_collect_(Path, Messages) :-
    load_files(user:Path, [if(true)]),
    findall(message(Kind, F, L, Text), api_load_message_(Kind, F, L, Text), Messages).

api_is_warning_(message(warning, _, _, _)).

api_capture_begin_ :-
    retractall(api_load_message_(_, _, _, _)),
    assertz(api_capturing_).

api_capture_end_ :-
    retractall(api_capturing_),
    retractall(api_load_message_(_, _, _, _)).

:- multifile user:message_hook/3.

%   While api_consult_/2 runs, record error and warning messages (and print
%   nothing): the reply carries them to Python.

user:message_hook(Term, Kind, Lines) :-
    api_capturing_,
    memberchk(Kind, [error, warning]),
    api_record_message_(Term, Kind, Lines).

api_record_message_(Term, Kind0, Lines) :-
    (   Term = error(syntax_error(_), _)
    ->  Kind = syntax_error
    ;   Kind = Kind0
    ),
    api_message_location_(Term, File, Line),
    with_output_to(string(Text0), print_message_lines(current_output, '', Lines)),
    split_string(Text0, "", "\n ", [Text]),
    assertz(api_load_message_(Kind, File, Line, Text)).

api_message_location_(Term, File, Line) :-
    (   Term = error(_, file(File0, Line0, _, _)),
        atom(File0)
    ->  File = File0,
        Line = Line0
    ;   Term = error(_, stream(Stream, Line0, _, _)),
        is_stream(Stream),
        stream_property(Stream, file_name(File0))
    ->  File = File0,
        Line = Line0
    ;   source_location(File0, Line0)
    ->  File = File0,
        Line = Line0
    ;   File = none,
        Line = none
    ).
