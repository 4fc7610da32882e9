:- module(experiment,
          [ learn_from_demonstration/3, % +Case, +Steps, -Result
            observed_state/3,      % +Case, +Primitive, -State
            plan_experiment/4,     % +Case, +VS, +Primitive, -Result
            plan_experiment/5,     % +Case, +VS, +Primitive, +Skip, -Result
            plan_experiment/6,     % +Case, +VS, +Primitive, +Skip, +Options, -Result
            plan_use/5,            % +Case, +VS, +Primitive, +Options, -Result
            label_trial/7,         % +Case, +VS0, +Experiment, +Primitive, +Label, +Mode, -VS
            task_objects/3,        % +Case, +State, -Objects
            next_experiment/6,     % +Case, +VS, +Objects, +Context, +Options, -Result
            experiment_strategies/1, % -Templates
            paper_candidates/2,    % +Problem, -Candidates
            informative_candidates/2, % +Problem, -Candidates
            feasible_experiment/3, % +Problem, +Candidates, -Experiment
            trial_example/6,       % +Case, +Tool, +Target, +Ctx, +Primitive, -Example
            literal_role/3,        % +Head, +Literal, -Role
            literal_prior/3,       % +Head, +Literal, -P
            hypothesis_parts/4     % +Clause, -Structural, -Spatial, -Task
          ]).

/** <module> Informative experiments for tool-use learning (the paper's Algorithm 1)

An experiment tests the *unknown* literals of the version space: literals of h_s that are
not (yet) in h_g. The experiment is built so that the trial example

  - is covered by h_g (otherwise the outcome is already known: failure), and
  - violates the tested literal and as few other literals of h_s as possible.

A success then drops the tested literal from h_s (the LGG of h_s with the new positive no
longer contains it); a failure makes it necessary in h_g (negative-based specialisation).

Structural literals are tested by choosing an *object* that violates them; spatial
literals by choosing a *pose* whose CLP(R) constraints negate them. The pose is always
produced by geometry_clp:solve_pose/5 from the required and negated spatial literals.

Roles of literals (literal_role/3), relative to the head tool_pose(Tool, Target, Ctx):

  - spatial: a literal with a spatial definition in the ontology (geometry_clp);
  - structural: mentions Tool and neither Target nor Ctx;
  - task: does not mention Tool (e.g. in_tube(cube1, tube1)).

The case's knowledge comes through these hook predicates of the ontology (case.pl says
how a missing one is reported), besides those of action_model.pl and abstract_state.pl:

  - untestable_literals(?Case, ?Patterns): spatial literals that are preconditions of
    the motion rather than pose choices, never tested (the hook: in_tube(_, _), the
    hook is always used inside the tube).
  - tool_acts_when(?Case, ?When): `held` if the tool acts in the robot's hand (the
    hook), `placed` if it acts once put down (the wedge: the spatial literals of a tool
    still in the gripper are left out of observed states).
  - learned_action_names(?Case, ?Names): name(Skill, Effect, Name) terms naming the
    action learned from the demonstration (observe:observe_demonstration/4's
    action_names/1 option).

The experiment strategies answer two hooks of this module, experiment_strategy/1 and
strategy_experiment/3, one clause group each (prolog/strategy.pl): they choose among the
candidates of paper_candidates/2 and informative_candidates/2.
*/

:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(error)).
:- use_module(library(option)).
:- use_module(library(ordsets)).
:- use_module(version_space).
:- use_module(lgg, []).
:- use_module(geometry_clp).
:- use_module(abstract_state).
:- use_module(observe).
:- use_module(action_model).
:- use_module(case).

:- multifile
    experiment_strategy/1,
    strategy_experiment/3.

%!  learn_from_demonstration(+Case, +Steps, -Result) is det.
%
%   Steps is the trainer's demonstration as step(Skill, Args, Primitive0, Primitive1)
%   with the primitive facts observed before and after each skill. The primitive facts
%   become abstract states (observed_state/3) and observe:observe_demonstration/4
%   builds the new action model. Result is models(Matched, New, Example) or the
%   observe module's error term (goal_not_reached(Goal), no_model(...)).

learn_from_demonstration(Case, Steps, Result) :-
    must_be(list, Steps),
    maplist(abstract_step_(Case), Steps, AbstractSteps),
    innate_action_models(Case, Models),
    action_task_goal(Case, Goal),
    case_answer(learned_action_names(Case, Names)),
    observe_demonstration(AbstractSteps, Models, [goal(Goal), action_names(Names)], Result).

abstract_step_(Case, step(Skill, Args, P0, P1), step(Skill, Args, S0, S1)) :-
    observed_state(Case, P0, S0),
    observed_state(Case, P1, S1).

%!  observed_state(+Case, +Primitive, -State) is det.
%
%   The abstract state of the primitive facts (abstract_state/3) plus the robot-state
%   literals the innate models speak of: holding(T) for a held tool (held/1 fact),
%   gripper_empty when nothing is held, and on_table(O) for every catalogued object
%   that is neither held nor placed (no spatial literal relates it to a target). In a
%   case whose tool acts once placed (tool_acts_when(Case, placed): the wedge) the
%   spatial literals speak of a tool put down, so those of a tool still in the gripper
%   are left out.

observed_state(Case, Primitive, State) :-
    abstract_state(Case, Primitive, Abstract0),
    case_answer(tool_acts_when(Case, When)),
    must_be(oneof([held, placed]), When),
    (   When == placed
    ->  exclude(held_spatial_(Primitive), Abstract0, Abstract)
    ;   Abstract = Abstract0
    ),
    findall(holding(T), member(held(T), Primitive), Holding),
    (   Holding == []
    ->  Grip = [gripper_empty]
    ;   Grip = []
    ),
    findall(on_table(O),
            ( catalogued_(Abstract, O),
              \+ memberchk(held(O), Primitive),
              \+ ( member(L, Abstract),
                    L =.. [_, O2, _],
                    O2 == O,
                    spatial_any_(L) )
            ),
            OnTable),
    append([Abstract, Holding, Grip, OnTable], State0),
    sort(State0, State).

held_spatial_(Primitive, L) :-
    compound(L),
    arg(1, L, O),
    memberchk(held(O), Primitive),
    spatial_any_(L).

catalogued_(Abstract, O) :-
    member(L, Abstract),
    catalogued_object(L, O).

spatial_any_(L) :-
    geometry_clp:spatial_literal(L).

%!  task_objects(+Case, +State, -Objects) is det.
%
%   The available objects of a state with their structural literals, as
%   object(Name, Literals) for next_experiment/6.

task_objects(_Case, State, Objects) :-
    findall(O, catalogued_(State, O), Os0),
    sort(Os0, Os),
    findall(object(O, Lits),
            ( member(O, Os),
              findall(L, ( member(L, State),
                           compound(L),
                           arg(1, L, A), A == O,
                           \+ spatial_any_(L),
                           \+ robot_literal_(L) ),
                      Lits)
            ),
            Objects).

robot_literal_(on_table(_)).
robot_literal_(holding(_)).

%!  plan_experiment(+Case, +VS, +Primitive, -Result) is det.
%
%   next_experiment/6 for the task described by the primitive facts Primitive (the
%   catalogue of available objects and the task's geometry). The target and context
%   objects are those of the version space's first positive example (the
%   demonstration).

plan_experiment(Case, VS, Primitive, Result) :-
    plan_experiment(Case, VS, Primitive, [], Result).

%!  plan_experiment(+Case, +VS, +Primitive, +Skip, -Result) is det.
%
%   As plan_experiment/4, leaving out the experiments skip(Object, Literal) of Skip:
%   those the arm could not carry out (unreachable or invalid in the physics), which
%   taught nothing and would be chosen again.

plan_experiment(Case, VS, Primitive, Skip, Result) :-
    plan_experiment(Case, VS, Primitive, Skip, [], Result).

%!  plan_experiment(+Case, +VS, +Primitive, +Skip, +Options, -Result) is det.
%
%   As plan_experiment/5 with the options of next_experiment/6 (strategy(S)).

plan_experiment(Case, VS, Primitive, Skip, Options, Result) :-
    must_be(list, Skip),
    must_be(list, Options),
    vs_examples(VS, [(tool_pose(_, Target, Ctx) :- _)|_], _),
    observed_state(Case, Primitive, State),
    task_objects(Case, State, Objects),
    next_experiment(Case, VS, Objects, Primitive,
                    [target(Target), context(Ctx), skip(Skip)|Options], Result).

%!  plan_use(+Case, +VS, +Primitive, +Options, -Result) is det.
%
%   Use the learned model without testing anything: the object that h_g covers and that
%   violates the fewest literals of h_s, at a pose satisfying every spatial literal of
%   h_s. Option tool(T) forces the object (a newly created tool, whose catalogue facts
%   must be among Primitive); h_g is then not required to cover it, since a created
%   tool differs from the learned model in the replaced literal by design. Result as the exploit/4 and no_experiment/1 results of
%   next_experiment/6.

plan_use(Case, VS, Primitive, Options, Result) :-
    vs_examples(VS, [(tool_pose(_, Target, Ctx) :- _)|_], _),
    observed_state(Case, Primitive, State),
    task_objects(Case, State, Objects0),
    (   option(tool(T), Options)
    ->  (   memberchk(object(T, Struct), Objects0)
        ->  Objects = [object(T, Struct)]
        ;   existence_error(object, T)
        )
    ;   Objects = Objects0
    ),
    vs_bounds(VS, HS, HG0),
    clause_head_body_(HS, Head, _),
    Head =.. [_, _, Target, Ctx],
    (   option(tool(_), Options)
    ->  HG = (Head :- true)      % a created tool violates h_g by design
    ;   HG = HG0
    ),
    hypothesis_parts(HS, _, Spatial, Task),
    exploit_(Case, HS, HG, Head, Spatial, Task, Objects, Primitive, Result).

%!  label_trial(+Case, +VS0, +Experiment, +Primitive, +Label, +Mode, -VS) is det.
%
%   Update the version space with the outcome of a trial. Label is pos or neg. Mode
%   observed builds the example from the primitive facts observed before the tool
%   action (trial_example/6); Mode planned builds it from the experiment's plan (the
%   object's structural literals, the required spatial literals and h_s's task
%   literals), used when the
%   motion was blocked and the observed state is not the one the experiment tested.

label_trial(Case, VS0, Experiment, Primitive, Label, Mode, VS) :-
    must_be(oneof([pos, neg]), Label),
    must_be(oneof([observed, planned]), Mode),
    experiment_object_(Experiment, Tool, Required),
    vs_examples(VS0, [(tool_pose(_, Target, Ctx) :- _)|_], _),
    (   Mode == observed
    ->  trial_example(Case, Tool, Target, Ctx, Primitive, Example)
    ;   observed_state(Case, Primitive, State),
        task_objects(Case, State, Objects),
        memberchk(object(Tool, Struct), Objects),
        vs_bounds(VS0, HS, _),
        clause_head_body_(HS, tool_pose(Tool, Target, Ctx), _),
        hypothesis_parts(HS, _, _, Task),
        append([Struct, Required, Task], Lits),
        list_to_conj_(Lits, Body),
        Example = (tool_pose(Tool, Target, Ctx) :- Body)
    ),
    Labelled =.. [Label, Example],
    vs_update(VS0, Labelled, VS).

experiment_object_(experiment(Tool, _, _, _, Required, _), Tool, Required).
experiment_object_(exploit(Tool, _, _, Required), Tool, Required).

%!  next_experiment(+Case, +VS, +Objects, +Context, +Options, -Result) is det.
%
%   Choose the next trial. Objects is a list of object(Name, StructuralLiterals) of the
%   available objects (ground literals as abstract_state/3 gives them); Context the
%   primitive facts of the task (tube or door geometry, the target's pose). Options:
%
%     - target(Target), context(Ctx): the head's second and third arguments (required).
%     - skip(Skip): experiments skip(Object, Literal) to leave out (default []);
%       skip(any, Literal) leaves out the literal whatever the object.
%     - strategy(S): how the experiment is chosen (default paper), one of the
%       strategies experiment_strategies/1 lists; prolog/strategy.pl defines paper
%       (the paper's Algorithm 1), informative (the largest expected reduction of the
%       version space) and random(Seed). An unknown strategy is a domain error naming
%       the declared ones.
%
%   The strategy's strategy_experiment/3 clause chooses the experiment from the
%   candidates of paper_candidates/2 or informative_candidates/2; when it chooses none,
%   the result is the learned model's use (exploit/4) or no_experiment/1.
%
%   Result is one of
%
%     - experiment(Object, Tested, Violated, Pose, Required, Negated): test the literal
%       Tested (a literal of h_s instantiated to the trial's objects) with Object at Pose
%       (the ground pose term of solve_pose/5); Violated lists every literal of h_s the
%       planned example violates (Tested among them: for informative, the negated
%       literal of a pose test, else the first in h_s order), Required/Negated the
%       spatial literals given to the constraint solver.
%     - exploit(Object, Violated, Pose, Required): nothing informative is left that the
%       available objects and poses can test; use the best object at an h_s pose. For
%       strategy informative this is the certified stop: no experiment the objects and
%       poses allow can change the version space.
%     - no_experiment(Reason): no object and pose satisfy h_g (Reason names the
%       literals of h_g that no object satisfies, or the infeasible pose literals).
%
%   ==
%   ?- next_experiment(hook, VS, Objects, Context, [target(cube1), context(tube1)], R).
%   R = experiment(hook_b4, hook_side(hook_b4, right), [hook_side(hook_b4, right)], ...)
%   ==

next_experiment(Case, VS, Objects, Context, Options, Result) :-
    must_be(list, Objects),
    must_be(list, Options),
    (   option(target(Target), Options),
        option(context(Ctx), Options)
    ->  true
    ;   domain_error(options_with(target(_), context(_)), Options)
    ),
    option(strategy(Strategy), Options, paper),
    must_be_strategy_(Strategy),
    vs_bounds(VS, HS, HG),
    clause_head_body_(HS, Head, _),
    Head =.. [_, _Tool, Target, Ctx],
    case_answer(untestable_literals(Case, Untestable)),
    option(skip(Skip), Options, []),
    Problem = experiment_problem(Case, VS, HS, HG, Objects, Context, Skip, Untestable),
    (   strategy_experiment(Strategy, Problem, Experiment)
    ->  Result = Experiment
    ;   hypothesis_parts(HS, _Struct, Spatial, Task),
        exploit_(Case, HS, HG, Head, Spatial, Task, Objects, Context, Result)
    ).

%!  experiment_strategy(?Template) is nondet.
%
%   Hook: Template declares a strategy of next_experiment/6, its name and arity, each
%   argument the type must_be/2 checks (random(integer)). One clause per strategy,
%   beside its strategy_experiment/3 clauses (prolog/strategy.pl): the strategies are
%   what these clauses declare.

%!  strategy_experiment(+Strategy, +Problem, -Experiment) is semidet.
%
%   Hook: the experiment that Strategy (an instance of its experiment_strategy/1
%   template) chooses for Problem, the trial's problem as next_experiment/6 builds it
%   (opaque: give it to paper_candidates/2, informative_candidates/2 and
%   feasible_experiment/3). Experiment is experiment(Object, Tested, Violated, Pose,
%   Required, Negated) as feasible_experiment/3 gives it; failing means that nothing
%   is left to test (next_experiment/6 then uses the learned model).

%!  experiment_strategies(-Templates) is det.
%
%   The declared strategies (experiment_strategy/1), in the order they were loaded.
%
%   ==
%   ?- experiment_strategies(Ts).
%   Ts = [paper, informative, random(integer)].
%   ==

experiment_strategies(Templates) :-
    findall(T, experiment_strategy(T), Templates).

must_be_strategy_(Strategy) :-
    experiment_strategies(Templates),
    (   var(Strategy)
    ->  instantiation_error(Strategy)
    ;   callable(Strategy),
        member(Template, Templates),
        functor(Template, Name, Arity),
        functor(Strategy, Name, Arity)
    ->  Template =.. [_|Types],
        Strategy =.. [_|Args],
        maplist(must_be, Types, Args)
    ;   domain_error(oneof(Templates), Strategy)
    ).

%!  paper_candidates(+Problem, -Candidates) is det.
%
%   The paper's candidates (Algorithm 1), in its order: every unknown literal of h_s
%   (in h_s, not in h_g; not a task literal nor an untestable one) with every object
%   that h_g covers, as cand(Tested, Object, Required, Negated, Violated). A structural
%   literal is tested by an object that violates it at an h_s pose, a spatial one by a
%   pose that negates it (Negated = [Tested]). The fewest literals of h_s violated come
%   first, then the literal's order in h_s, then the object's name; the experiments of
%   the problem's skip list are left out.

paper_candidates(experiment_problem(Case, _VS, HS, HG, Objects, _Context, Skip,
                                    Untestable),
                 Cands) :-
    clause_head_body_(HS, Head, _),
    hypothesis_parts(HS, _Struct, Spatial, Task),
    unknown_literals_(HS, HG, Unknown),
    findall(Score-cand(L, O, Req, Neg, Viol),
            candidate_(Case, Untestable, HS, HG, Head, Unknown, Spatial, Task, Objects,
                       L, O, Req, Neg, Viol, Score),
            Scored),
    exclude(skipped_(Skip), Scored, Scored1),
    keysort(Scored1, Sorted),
    pairs_values(Sorted, Cands).

%!  feasible_experiment(+Problem, +Candidates, -Experiment) is semidet.
%
%   The first of Candidates (cand/5 terms) whose pose constraints have a solution
%   (solve_pose/5), as experiment(Object, Tested, Violated, Pose, Required, Negated);
%   fails when none has.

feasible_experiment(experiment_problem(Case, _, _, _, _, Context, _, _), Cands,
                    experiment(O, L, Viol, Pose, Req, Neg)) :-
    first_feasible_(Case, Cands, Context, cand(L, O, Req, Neg, Viol), Pose).

%!  informative_candidates(+Problem, -Candidates) is semidet.
%
%   The candidates of the informative strategy, the most informative first. The
%   hypotheses are those of version_space:vs_space/4:
%   subsets of h_s's literals that exclude every recorded negative. A candidate
%   experiment is an object at an h_s pose, or at a pose that negates one spatial
%   literal of h_s (any object, covered by h_g or not); V is the set of literals of
%   h_s its planned example violates. Under a hypothesis H the trial succeeds exactly
%   when H keeps none of V, so a success leaves the N_s hypotheses without V and a
%   failure the N - N_s others. With p the prior probability of success (the mass of
%   the hypotheses without V, literal_prior/3), the expected reduction is
%
%       R = p (N - N_s) + (1 - p) N_s
%
%   and the largest R comes first (after a prior, --prior: the experiments that put
%   fewer of the prior's open literals at risk come first, whatever their R, so the
%   prior's predictions are tested after what it says nothing about, and a success in
%   between can settle them, version_space:vs_init_prior/3); ties go to the likelier
%   success (a success also
%   moves the task on and shrinks h_s, which can turn an object that violates several
%   literals into a test of one), then to fewer violated literals, to the earlier
%   literals of h_s, and to the object's name. An experiment whose outcome every
%   hypothesis agrees on (N_s = 0 or N_s = N) cannot change the version space and is
%   not a candidate: when none is left (or none has a feasible pose), nothing can
%   change the version space, which is the certified stop. The predicate fails when
%   the count is not exact (more than 20 literals in the negatives' violation sets,
%   vs_count/3), where the expected reduction cannot be computed.

informative_candidates(experiment_problem(Case, VS, HS0, _, Objects, _, Skip,
                                          Untestable),
                       Cands) :-
    vs_space(VS, HS, Lits, Cs),
    ord_union(Cs, Used),
    length(Used, NUsed),
    NUsed =< 20,                    % the count is exact (vs_count/3)
    clause_head_body_(HS0, Head0, _),
    Head0 =.. [_, _, Target, Ctx],
    clause_head_body_(HS, Head, _),
    Head =.. [_, _, Target, Ctx],
    maplist(literal_prior(Head), Lits, Priors0),
    vs_prior_open(VS, Open),
    prior_open_priors_(Priors0, 1, Open, Priors),
    vs_space_count(Lits, Cs, [], Priors, N-W),
    hypothesis_parts(HS, _, Spatial, Task),
    findall(Key-Cand,
            informative_candidate_(Case, Untestable, HS, Head, Lits, Cs, Priors, N, W,
                                   Spatial, Task, Objects, Open, Key, Cand),
            Scored),
    exclude(skipped_(Skip), Scored, Scored1),
    keysort(Scored1, Sorted),
    pairs_values(Sorted, Cands).

informative_candidate_(Case, Untestable, HS, Head, Lits, Cs, Priors, N, W, Spatial, Task,
                       Objects, Open, k(NOpen, NegR, NegP, K, PosV, O),
                       cand(L, O, Req, Neg, Viol)) :-
    member(object(O, Struct), Objects),
    copy_term(Head-(Spatial-Task-Lits), HeadC-(SpatialC-TaskC-LitsC)),
    HeadC =.. [_, O|_],
    append([Struct, SpatialC, TaskC], Body),
    list_to_conj_(Body, Conj),
    clause_violations(HS, (HeadC :- Conj), Viol0),
    vs_space_positions(Lits, Viol0, Pos0),
    (   Req = SpatialC,
        Neg = [],
        PosV = Pos0
    ;   nth1(I, LitsC, LC),
        \+ ord_memberchk(I, Pos0),
        literal_role(HeadC, LC, spatial),
        testable_spatial_(Case, LC),
        \+ ( member(Pattern, Untestable), Pattern = LC ),
        exclude(==(LC), SpatialC, Req),
        Neg = [LC],
        ord_add_element(Pos0, I, PosV)
    ),
    PosV = [First|_],
    vs_space_count(Lits, Cs, PosV, Priors, NS-WS),
    NS > 0,
    NS < N,
    P is WS rdiv W,
    R is P * (N - NS) + (1 - P) * NS,
    NegR is -R,
    NegP is -P,
    length(PosV, K),
    ord_intersection(PosV, Open, OpenV),
    length(OpenV, NOpen),
    findall(V, ( member(J, PosV), nth1(J, LitsC, V) ), Viol),
    (   Neg = [L]                   % a pose test is named by its negated literal
    ->  true
    ;   nth1(First, LitsC, L)
    ).

%!  literal_prior(+Head, +Literal, -P) is det.
%
%   The prior probability that Literal of h_s is necessary, used by the informative
%   strategy, from the literal's kind (literal_role/3), the same for every case:
%
%     - spatial (how the trainer placed the tool relative to the target): 3/4; the
%       demonstrator chose the pose, so its relations are likely meant;
%     - a class literal (structural, one argument: hook(T), block(T)): 1/2;
%     - any other structural literal (a property of the demonstrated tool:
%       handle_length(T, medium)): 2/5; a tool has many properties and few matter;
%     - a task literal: 1/2 (no experiment changes it, so it never weighs).
%
%   What earlier trials showed enters through the version space itself: the prior is
%   conditioned on the hypotheses that are left (a failure makes at least one of its
%   violated literals necessary; a success removes its violated literals from h_s).
%   With 2/5, a pair of properties is never chosen over a single free one (a pair
%   succeeds with probability 9/25 and has R = 0.43 N against 0.5 N): several literals
%   are violated together when no single test is left or when earlier trials made
%   their necessity unlikely.

%   The literals a prior predicts necessary and the physics has not yet settled
%   (version_space:vs_prior_open/2): 9/10, whatever their kind; they stay hypotheses to
%   test, tried after the literals the prior says nothing about.
prior_open_priors_([], _, _, []).
prior_open_priors_([P0|Ps0], I, Open, [P|Ps]) :-
    (   ord_memberchk(I, Open)
    ->  P = 9r10
    ;   P = P0
    ),
    I1 is I + 1,
    prior_open_priors_(Ps0, I1, Open, Ps).

literal_prior(Head, L, P) :-
    literal_role(Head, L, Role),
    (   Role == spatial
    ->  P = 3r4
    ;   Role == structural,
        functor(L, _, 1)
    ->  P = 1r2
    ;   Role == structural
    ->  P = 2r5
    ;   P = 1r2
    ).

candidate_(Case, Untestable, HS, HG, Head, Unknown, Spatial, Task, Objects,
           L, O, Req, Neg, Viol, Score) :-
    objects_as_planned_(HS, HG, Head, Spatial, Task, Objects, Planned),
    nth1(Index, Unknown, L0),
    literal_role(Head, L0, Role),
    Role \== task,
    \+ ( member(Pattern, Untestable), Pattern = L0 ),
    member(planned(O, HeadC, SpatialC, Viol0), Planned),
    copy_term(Head-L0, HeadC-L),
    (   Role == spatial
    ->  testable_spatial_(Case, L),
        exclude(==(L), SpatialC, Req),
        Neg = [L],
        append(Viol0, [L], Viol)     % the pose leaves out L, and only L
    ;   Req = SpatialC,
        Neg = [],
        Viol = Viol0
    ),
    memberchk_eq_(L, Viol),
    length(Viol, NV),
    Score = s(NV, Index, O).

%   The example each object would give at an h_s pose, and the literals of h_s it
%   violates, computed once per object (the experiments of one object differ only in
%   the one spatial literal they negate). Objects h_g does not cover are left out: their
%   outcome is already known.
objects_as_planned_(HS, HG, Head, Spatial, Task, Objects, Planned) :-
    findall(planned(O, HeadC, SpatialC, Viol),
            ( member(object(O, Struct), Objects),
              copy_term(Head-(Spatial-Task), HeadC-(SpatialC-TaskC)),
              HeadC =.. [_, O|_],
              append([Struct, SpatialC, TaskC], Body),
              list_to_conj_(Body, Conj),
              Example = (HeadC :- Conj),
              clause_covers_hg_(HG, Example),
              clause_violations(HS, Example, Viol0),
              instantiate_violations_(HS, Example, Viol0, Viol)
            ),
            Planned).

skipped_(Skip, _-cand(L, O, _, _, _)) :-
    member(skip(O1, L1), Skip),
    (   O1 == any
    ->  same_literal_any_tool_(L1, L)
    ;   O1 == O,
        L1 =@= L
    ),
    !.

%   skip(any, L): the literal L whatever the tool (a pose the arm cannot reach is
%   unreachable with every tool).
same_literal_any_tool_(L1, L) :-
    L1 =.. [F, _|As1],
    L =.. [F, _|As],
    As1 =@= As.

%   A spatial literal can be tested when the ontology defines it for the constraint
%   solver (in_tube/2 of the tool, for example, is a precondition of the motion, not a
%   pose choice).
testable_spatial_(Case, L) :-
    geometry_clp:spatial_literal(Case, L).

first_feasible_(Case, [C|Cs], Context, Chosen, Pose) :-
    C = cand(_, _, Req, Neg, _),
    solve_pose(Case, Req, Neg, Context, R),
    (   R = pose(Pose)
    ->  Chosen = C
    ;   first_feasible_(Case, Cs, Context, Chosen, Pose)
    ).

exploit_(Case, HS, HG, Head, Spatial, Task, Objects, Context, Result) :-
    findall(NV-e(O, Viol, Req),
            ( member(object(O, Struct), Objects),
              copy_term(Head-(Spatial-Task), HeadC-(Req-TaskC)),
              HeadC =.. [_, O|_],
              append([Struct, Req, TaskC], Body),
              list_to_conj_(Body, Conj),
              Example = (HeadC :- Conj),
              clause_covers_hg_(HG, Example),
              clause_violations(HS, Example, Viol0),
              instantiate_violations_(HS, Example, Viol0, Viol),
              length(Viol, NV)
            ),
            Scored),
    keysort(Scored, Sorted),
    (   Sorted = [_-e(O, Viol, Req)|_]
    ->  solve_pose(Case, Req, [], Context, R),
        (   R = pose(Pose)
        ->  Result = exploit(O, Viol, Pose, Req)
        ;   R = infeasible(Conflict),
            Result = no_experiment(infeasible_pose(Conflict))
        )
    ;   clause_head_body_(HG, _, HGBody),
        conj_to_list_(HGBody, HGLits),
        Result = no_experiment(no_object_satisfies(HGLits))
    ).

clause_covers_hg_(HG, Example) :-
    clause_covers(HG, Example).

%   clause_violations/3 returns the literals as they appear in the clause; give them the
%   example's objects by unifying a copy of the clause's head with the example's head.
instantiate_violations_(HS, (EH :- _), Viol0, Viol) :-
    clause_head_body_(HS, H, _),
    copy_term(H-Viol0, H1-Viol),
    H1 = EH.

memberchk_eq_(X, [Y|Ys]) :-
    (   X =@= Y
    ->  true
    ;   memberchk_eq_(X, Ys)
    ).

%   The unknown literals: those of h_s's body not in h_g's body (vs_bounds/3 returns
%   the two clauses sharing their head variables, so == compares them).
unknown_literals_(HS, HG, Unknown) :-
    clause_head_body_(HS, _, HSBody),
    clause_head_body_(HG, _, HGBody),
    conj_to_list_(HSBody, HSLits),
    conj_to_list_(HGBody, HGLits),
    exclude(in_list_eq_(HGLits), HSLits, Unknown0),
    exclude(is_in_range_, Unknown0, Unknown).

in_list_eq_(List, X) :-
    member(Y, List),
    Y == X,
    !.

%!  hypothesis_parts(+Clause, -Structural, -Spatial, -Task) is det.
%
%   Split the body of a hypothesis tool_pose(Tool, Target, Ctx) :- Body by
%   literal_role/3. in_range/3 interval literals are left out.

hypothesis_parts(Clause, Structural, Spatial, Task) :-
    clause_head_body_(Clause, Head, Body),
    conj_to_list_(Body, Lits0),
    exclude(is_in_range_, Lits0, Lits),
    partition_roles_(Lits, Head, Structural, Spatial, Task).

partition_roles_([], _, [], [], []).
partition_roles_([L|Ls], Head, St, Sp, Ta) :-
    literal_role(Head, L, Role),
    (   Role == structural
    ->  St = [L|St1], Sp = Sp1, Ta = Ta1
    ;   Role == spatial
    ->  St = St1, Sp = [L|Sp1], Ta = Ta1
    ;   St = St1, Sp = Sp1, Ta = [L|Ta1]
    ),
    partition_roles_(Ls, Head, St1, Sp1, Ta1).

is_in_range_(in_range(_, _, _)).

%!  literal_role(+Head, +Literal, -Role) is det.
%
%   Role of a body literal relative to the head tool_pose(Tool, Target, Ctx): spatial,
%   structural or task (see the module header).

literal_role(Head, L, Role) :-
    Head =.. [_, Tool|_],
    (   spatial_any_(L),
        arg(1, L, A),
        A == Tool
    ->  Role = spatial
    ;   term_variables(L, _),
        mentions_(L, Tool)
    ->  Role = structural
    ;   Role = task
    ).

mentions_(L, X) :-
    L =.. [_|Args],
    member(A, Args),
    A == X,
    !.

%!  trial_example(+Case, +Tool, +Target, +Ctx, +Primitive, -Example) is det.
%
%   The ground example of a trial: the head tool_pose(Tool, Target, Ctx) and every
%   abstract literal of the state before the tool action (Primitive: primitive facts)
%   that mentions Tool, Target or Ctx, structural literals of other objects left out.

trial_example(Case, Tool, Target, Ctx, Primitive, (Head :- Body)) :-
    Head = tool_pose(Tool, Target, Ctx),
    abstract_state(Case, Primitive, Abstract),
    include(relevant_literal_(Tool, Target, Ctx), Abstract, Lits0),
    sort(0, @<, Lits0, Lits1),
    order_literals_(Head, Lits1, Lits),
    list_to_conj_(Lits, Body).

relevant_literal_(Tool, Target, Ctx, L) :-
    L =.. [_|Args],
    (   memberchk(Tool, Args)
    ->  true
    ;   Args \== [],
        forall(member(A, Args), memberchk(A, [Target, Ctx]))
    ).

%   Structural, then spatial, then task literals: the order people read clauses in.
order_literals_(Head, Lits, Ordered) :-
    partition_roles_(Lits, Head, St, Sp, Ta),
    append([St, Sp, Ta], Ordered).

clause_head_body_((H :- B), H, B) :- !.
clause_head_body_(H, H, true).

conj_to_list_(true, []) :- !.
conj_to_list_((A, B), [A|L]) :- !,
    conj_to_list_(B, L).
conj_to_list_(A, [A]).

list_to_conj_([], true).
list_to_conj_([L], L) :- !.
list_to_conj_([L|Ls], (L, C)) :-
    list_to_conj_(Ls, C).
