:- module(model_file,
          [ write_model_file/4,   % +File, +Case, +Models, +VS
            load_model_file/1,    % +File
            learned_action_models/3, % +Models, +VS, -Learned
            plan_task/6,          % +Case, +Models, +VS, +Primitive, +Options, -Result
            plan_models/5,        % +Case, +Learned, +Primitive, +Options, -Result
            created_models/5,     % +Models, +VS, +Replaced, +Instance, -Created
            write_model_file/5    % +File, +Case, +Models, +VS, +Created
          ]).

/** <module> A run's learned model as a file a Prolog REPL can load

model.pl holds plain terms, one per clause, with a header comment:

    learned_model(Task, Action, Pre, Eff).       % Eff: [add(L), ..., del(L), ...]
    learned_hypothesis(Task, hs, Clause).         % the version space's boundaries
    learned_hypothesis(Task, hg, Clause).
    learned_hypothesis(Task, prior, Clause).      % a run with a prior: h_g's literals
                                                  % from it (transfer.pl)

The learned model's precondition is the observed model's literals about the robot and
the task (holding the tool, the cube in the tube, the door open), then h_g: the literals the physics showed necessary. load_model_file/1 reads the terms
(raising on a syntax error, with file and line) and adds them to the knowledge base,
where knowledge:learned_model/4 answers queries.
*/

:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(error)).
:- use_module(library(readutil)).
:- use_module(library(yall)).
:- use_module(knowledge, [kb_assert_learned/1]).
:- use_module(version_space, [vs_bounds/3, vs_prior_clause/2]).
:- use_module(experiment, [hypothesis_parts/4, observed_state/3]).
:- use_module(library(option)).
:- use_module(action_model, [innate_action_models/2, action_task_goal/2,
                              tool_literal_kind/3, case_tool_objects/3]).
:- use_module(planner, [plan/5]).
:- use_module(pddl, [pddl_write_files/6]).
:- use_module(case, [case_answer/1]).

%!  write_model_file(+File, +Case, +Models, +VS) is det.
%
%   Write the learned action models Models (action_model/5 terms from observation) with
%   their preconditions rewritten from the final version space VS, and VS's two
%   boundary clauses, to File.

write_model_file(File, Case, Models, VS) :-
    must_be(atom, Case),
    vs_bounds(VS, HS, HG),
    setup_call_cleanup(
        open(File, write, Out, [encoding(utf8)]),
        ( format(Out, '%   Learned by CREATIVE-py, case ~w.~n', [Case]),
          format(Out, '%   Load: swipl prolog/creative.pl, then ?- load_model_file(\'~w\').~n', [File]),
          format(Out, '%   learned_model(Task, Action, Precondition, Effects): Precondition is~n', []),
          format(Out, '%   the skill\'s own precondition, the most general hypothesis h_g, then~n', []),
          format(Out, '%   the spatial literals of h_s that h_g lacks (the pose that worked).~n', []),
          format(Out, '%   learned_hypothesis(Task, hs|hg, Clause): the version space\'s bounds.~n~n', []),
          % The created tool's models are appended after the hypotheses: consulted
          % with swipl, the file then loads without a discontiguous warning.
          format(Out, ':- discontiguous learned_model/4.~n~n', []),
          forall(member(M, Models), write_model_(Out, Case, M, HS-HG)),
          nl(Out),
          portray_clause(Out, learned_hypothesis(Case, hs, HS)),
          portray_clause(Out, learned_hypothesis(Case, hg, HG)),
          (   vs_prior_clause(VS, Prior)
          ->  format(Out, '%   The literals of h_g from a prior case\'s learned model (--prior): settled by a~n', []),
              format(Out, '%   success (untested: the stop is certified relative to them) or made necessary~n', []),
              format(Out, '%   by a failure (summary.json use.prior says which).~n', []),
              portray_clause(Out, learned_hypothesis(Case, prior, Prior))
          ;   true
          )
        ),
        close(Out)).

write_model_(Out, Case, Model, HS-HG) :-
    learned_model_(Model, HS-HG, action_model(Name, Params, Pre1, Add, Del)),
    pairs_keys_(Params, Vars),
    Action =.. [Name|Vars],
    effects_(Add, Del, Eff),
    portray_clause(Out, learned_model(Case, Action, Pre1, Eff)).

%   add(L) and del(L) terms; maplist/3, not findall/3, so that the effects keep sharing
%   variables with the action's arguments.
effects_(Add, Del, Eff) :-
    maplist([L, add(L)]>>true, Add, As),
    maplist([L, del(L)]>>true, Del, Ds),
    append(As, Ds, Eff).

%   The observed model with its precondition rewritten: the skill's own literals, then
%   h_g's body, then the spatial literals of h_s that h_g lacks (the pose the robot
%   puts the tool in: a pose must be chosen anyway, and h_s's is the one that worked).
%   Interval literals are left out: a planner has no use for them.
learned_model_(action_model(Name, Params, Pre, Add, Del), HS-HG,
               action_model(Name, Params, Pre1, Add, Del)) :-
    pairs_keys_(Params, Vars),
    copy_term(HS-HG, HS1-HG1),
    clause_parts_(HS1, HSHead, HSBody),
    clause_parts_(HG1, HGHead, HGBody),
    HSHead = HGHead,
    (   Vars = [T, C, X | _]
    ->  HGHead =.. [_, T, C, X]
    ;   true
    ),
    conj_list_(HGBody, HGLits1),
    hypothesis_parts((HSHead :- HSBody), _, HSSpatial, _),
    exclude(in_list_eq_(HGLits1), HSSpatial, ExtraSpatial),
    append(HGLits1, ExtraSpatial, HGLits0),
    exclude(interval_literal_, HGLits0, HGLits),
    (   Vars = [Tool|_]
    ->  include(not_tool_literal_(Tool), Pre, Skill)
    ;   Skill = Pre
    ),
    append(Skill, HGLits, Pre1).

%   The model's own precondition literals that h_g does not speak of: the robot's
%   state and the task's (holding(T), door_open(D), in_tube(C, Tube)).
not_tool_literal_(Tool, L) :-
    tool_literal_kind(Tool, L, Kind),
    memberchk(Kind, [robot, other]).

interval_literal_(in_range(_, _, _)).

clause_parts_((H :- B), H, B) :- !.
clause_parts_(H, H, true).

in_list_eq_(List, X) :-
    member(Y, List),
    Y == X,
    !.

%!  learned_action_models(+Models, +VS, -Learned) is det.
%
%   The new action models of a demonstration with their preconditions rewritten from
%   the final version space: the skill's own precondition, then h_g, then the spatial
%   literals of h_s that h_g lacks.

learned_action_models(Models, VS, Learned) :-
    vs_bounds(VS, HS, HG),
    learned_models_(Models, HS-HG, Learned).

learned_models_([], _, []).
learned_models_([M|Ms], HG, [L|Ls]) :-
    learned_model_(M, HG, L),
    learned_models_(Ms, HG, Ls).

%!  plan_task(+Case, +Models, +VS, +Primitive, +Options, -Result) is det.
%
%   Plan the case's task in the state described by the primitive facts, with the
%   innate skills and the learned models (learned_action_models/3). Options:
%   pddl(DomainFile, ProblemFile) also writes the PDDL files; the planner's own options
%   (max_depth/1) are passed on. Result is planner:plan/5's: plan(Steps) or
%   no_plan(Reason), no_plan(no_object_satisfies(Model, Failed)) being the trigger for
%   tool creation.

plan_task(Case, Models, VS, Primitive, Options, Result) :-
    learned_action_models(Models, VS, Learned),
    plan_models(Case, Learned, Primitive, Options, Result).

%!  plan_models(+Case, +Learned, +Primitive, +Options, -Result) is det.
%
%   As plan_task/6, with the learned action models given as they are (Learned, e.g.
%   the harder task's models of created_models/5) instead of rewritten from a version
%   space: plan the case's task in the state of the primitive facts with Learned and
%   the innate skills. Both the planner and the PDDL problem type as a tool every
%   object of the case's tool hierarchy (action_model:case_tool_objects/3), whatever
%   the models' preconditions keep of its class literals. Option
%   pddl(DomainFile, ProblemFile) also writes the PDDL files
%   (pddl:pddl_write_files/6 with the case's tool typing), named after the options
%   domain_name(N) (default `creative`) and problem_name(N) (default `task`); the
%   planner's own options are passed on.

plan_models(Case, Learned, Primitive, Options, Result) :-
    must_be(list, Learned),
    innate_action_models(Case, Innate),
    append(Learned, Innate, All),
    observed_state(Case, Primitive, State),
    action_task_goal(Case, Goal),
    case_answer(case_extra_objects(Case, Extra0)),
    case_tool_objects(Case, State, Tools),
    findall(T-tool, ( member(T, Tools), \+ memberchk(T-_, Extra0) ), ToolObjects),
    append(Extra0, ToolObjects, Extra),
    (   option(pddl(Dom, Prob), Options)
    ->  option(domain_name(DomainName), Options, creative),
        option(problem_name(ProblemName), Options, task),
        pddl_write_files(Dom, Prob, All, State, Goal,
                         [objects(Extra), case(Case), domain_name(DomainName),
                          problem_name(ProblemName)])
    ;   true
    ),
    exclude(pddl_option_, Options, PlanOptions),
    plan(State, Goal, All, [objects(Extra)|PlanOptions], Result).

pddl_option_(pddl(_, _)).
pddl_option_(domain_name(_)).
pddl_option_(problem_name(_)).

pairs_keys_([], []).
pairs_keys_([K-_|Ps], [K|Ks]) :-
    pairs_keys_(Ps, Ks).

conj_list_(true, []) :- !.
conj_list_((A, B), [A|L]) :- !,
    conj_list_(B, L).
conj_list_(A, [A]).

%!  created_models(+Models, +VS, +Replaced, +Instance, -Created) is det.
%
%   The action models for a task that needed a created tool: the learned models
%   (learned_action_models/3) with the replaced structural literal of the tool swapped
%   for the created tool's value, e.g. block_length(W, medium) for block_length(W, long).
%   This is the paper's "new category": the tool the harder task needs.

created_models(Models, VS, Replaced, Instance, Created) :-
    learned_action_models(Models, VS, Learned),
    maplist(swap_literal_(Replaced, Instance), Learned, Created).

swap_literal_(Replaced, Instance, action_model(N, Params, Pre0, Add, Del),
              action_model(N, Params, Pre, Add, Del)) :-
    Params = [Tool-_|_],
    maplist(swap_one_(Tool, Replaced, Instance), Pre0, Pre1),
    (   Pre1 == Pre0
    ->  copy_term(Instance, I),
        setarg(1, I, Tool),
        append(Pre0, [I], Pre)
    ;   Pre = Pre1
    ).

swap_one_(Tool, Replaced, Instance, L0, L) :-
    (   compound(L0),
        arg(1, L0, A), A == Tool,
        copy_term(Replaced, R), R =.. [F|[_|RArgs]],
        L0 =.. [F, _|LArgs], LArgs =@= RArgs
    ->  copy_term(Instance, I),
        I =.. [IF, _|IArgs],
        L =.. [IF, Tool|IArgs]
    ;   L = L0
    ).

%!  write_model_file(+File, +Case, +Models, +VS, +Created) is det.
%
%   As write_model_file/4, then the models of the harder task: Created is a list of
%   created(Variant, Models) (created_models/5), written as learned_model(Case-Variant,
%   ...) terms.

write_model_file(File, Case, Models, VS, Created) :-
    write_model_file(File, Case, Models, VS),
    setup_call_cleanup(
        open(File, append, Out, [encoding(utf8)]),
        forall(member(created(Variant, Ms), Created),
               ( format(Out, '~n%   The task variant ~w needed a created tool.~n', [Variant]),
                 forall(member(action_model(N, Ps, Pre, Add, Del), Ms),
                        ( pairs_keys_(Ps, Vs),
                          A =.. [N|Vs],
                          effects_(Add, Del, Eff),
                          portray_clause(Out, learned_model(Case-Variant, A, Pre, Eff))
                        ))
               )),
        close(Out)).

%!  load_model_file(+File) is det.
%
%   Read a model.pl written by write_model_file/4 and add its terms to the knowledge
%   base (its directives, written for a consulting swipl, are skipped). A missing file
%   raises existence_error(source_sink, File); a syntax error raises with the file and
%   line; any other term raises a domain_error.

load_model_file(File) :-
    must_be(atom, File),
    (   exists_file(File)
    ->  true
    ;   existence_error(source_sink, File)
    ),
    setup_call_cleanup(
        open(File, read, In, [encoding(utf8)]),
        read_all_(In, Terms),
        close(In)),
    maplist(kb_assert_learned, Terms).

read_all_(In, Terms) :-
    read_term(In, T, []),
    (   T == end_of_file
    ->  Terms = []
    ;   T = (:- _)                      % a directive for swipl (discontiguous/1)
    ->  read_all_(In, Terms)
    ;   Terms = [T|Ts],
        read_all_(In, Ts)
    ).
