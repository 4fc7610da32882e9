:- module(model_file,
          [ write_model_file/4,   % +File, +Case, +Models, +VS
            load_model_file/1     % +File
          ]).

/** <module> A run's learned model as a file a Prolog REPL can load

model.pl holds plain terms, one per clause, with a header comment:

    learned_model(Task, Action, Pre, Eff).       % Eff: [add(L), ..., del(L), ...]
    learned_hypothesis(Task, hs, Clause).         % the version space's boundaries
    learned_hypothesis(Task, hg, Clause).

The learned model's precondition is the skill's own precondition (holding the tool),
then h_g: the literals the physics showed necessary. load_model_file/1 reads the terms
(raising on a syntax error, with file and line) and adds them to the knowledge base,
where knowledge:learned_model/4 answers queries.
*/

:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(error)).
:- use_module(library(readutil)).
:- use_module(knowledge, [kb_assert_learned/1]).
:- use_module(version_space, [vs_bounds/3]).
:- use_module(experiment, [hypothesis_parts/4]).

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
          format(Out, '%   the skill\'s own precondition and the most general hypothesis h_g.~n', []),
          format(Out, '%   learned_hypothesis(Task, hs|hg, Clause): the version space\'s bounds.~n~n', []),
          forall(member(M, Models), write_model_(Out, Case, M, HG)),
          nl(Out),
          portray_clause(Out, learned_hypothesis(Case, hs, HS)),
          portray_clause(Out, learned_hypothesis(Case, hg, HG))
        ),
        close(Out)).

write_model_(Out, Case, action_model(Name, Params, Pre, Add, Del), HG) :-
    pairs_keys_(Params, Vars),
    Action =.. [Name|Vars],
    copy_term(HG, (HGHead :- HGBody)),
    (   Vars = [T, C, X | _]
    ->  HGHead =.. [_, T, C, X]
    ;   true
    ),
    conj_list_(HGBody, HGLits),
    include(skill_literal_, Pre, Skill),
    append(Skill, HGLits, Pre1),
    findall(add(L), member(L, Add), As),
    findall(del(L), member(L, Del), Ds),
    append(As, Ds, Eff),
    portray_clause(Out, learned_model(Case, Action, Pre1, Eff)).

pairs_keys_([], []).
pairs_keys_([K-_|Ps], [K|Ks]) :-
    pairs_keys_(Ps, Ks).

skill_literal_(holding(_)).
skill_literal_(gripper_empty).

conj_list_(true, []) :- !.
conj_list_((A, B), [A|L]) :- !,
    conj_list_(B, L).
conj_list_(A, [A]).

%!  load_model_file(+File) is det.
%
%   Read a model.pl written by write_model_file/4 and add its terms to the knowledge
%   base. A missing file raises existence_error(source_sink, File); a syntax error
%   raises with the file and line; any other term raises a domain_error.

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
    ;   Terms = [T|Ts],
        read_all_(In, Ts)
    ).
