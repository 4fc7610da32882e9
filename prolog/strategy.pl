:- module(strategy, []).

/** <module> The experiment strategies of tool-use learning, one clause group each

A strategy is one clause group of experiment's two hooks:

  - experiment:experiment_strategy(Template): declares the strategy, its name and
    arity, each argument the type must_be/2 checks. experiment:next_experiment/6
    accepts exactly the declared strategies (experiment_strategies/1 lists them).
  - experiment:strategy_experiment(Strategy, Problem, Experiment): the experiment the
    strategy chooses for the trial's Problem, built from the candidates of
    experiment:paper_candidates/2 or experiment:informative_candidates/2 and made
    concrete by experiment:feasible_experiment/3; it fails when the strategy proposes
    no experiment (next_experiment/6 then uses the learned model, and the learner
    stops by the strategy's rule, creative_py/learning/strategies.py).

Adding a strategy is one clause group here (or in any file loaded after experiment.pl:
a test defines one in tests/prolog/experiment.plt) and one entry of Python's registry
(docs/architecture.md, "Adding a strategy").

==
?- experiment:experiment_strategies(Ts).
Ts = [paper, informative, random(integer)].
==
*/

:- use_module(library(lists)).
:- use_module(library(random)).
:- use_module(experiment, [paper_candidates/2, informative_candidates/2,
                           feasible_experiment/3]).

:- discontiguous
    experiment:experiment_strategy/1,
    experiment:strategy_experiment/3.

%   paper: the paper's Algorithm 1. Every unknown literal with every object that h_g
%   covers; the fewest literals of h_s violated wins, then the literal's order in h_s,
%   then the object's name.
experiment:experiment_strategy(paper).
experiment:strategy_experiment(paper, Problem, Experiment) :-
    paper_candidates(Problem, Cands),
    feasible_experiment(Problem, Cands, Experiment).

%   informative: the experiment with the largest expected reduction of the version
%   space (experiment:informative_candidates/2). It may violate several unknown
%   literals at once, and needs no h_g cover (after a failure of several literals h_g
%   holds one of them, chosen greedily, and the others still have to be split). None
%   left is the certified stop. Where the count would not be exact, the paper's order.
experiment:experiment_strategy(informative).
experiment:strategy_experiment(informative, Problem, Experiment) :-
    (   informative_candidates(Problem, Cands)
    ->  true
    ;   paper_candidates(Problem, Cands)
    ),
    feasible_experiment(Problem, Cands, Experiment).

%   random(Seed): a random experiment among the paper's candidates (those h_g covers),
%   drawn with SWI-Prolog's random generator seeded with Seed. One object at one pose
%   is one experiment, whichever of its violated literals names it.
experiment:experiment_strategy(random(integer)).
experiment:strategy_experiment(random(Seed), Problem, Experiment) :-
    paper_candidates(Problem, Cands0),
    distinct_experiments_(Cands0, [], Distinct),
    set_random(seed(Seed)),
    random_permutation(Distinct, Cands),
    feasible_experiment(Problem, Cands, Experiment).

distinct_experiments_([], _, []).
distinct_experiments_([C|Cs], Seen, Out) :-
    C = cand(_, O, _, Neg, _),
    (   member(Seen1, Seen),
        Seen1 =@= O-Neg
    ->  Out = Out1
    ;   Out = [C|Out1]
    ),
    distinct_experiments_(Cs, [O-Neg|Seen], Out1).
