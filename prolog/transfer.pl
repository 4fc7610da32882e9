:- module(transfer,
          [ read_prior/2,            % +File, -Prior
            read_prior_text/3,       % +Text, +File, -Prior
            prior_shared/3,          % +Case, +Prior, -Shared
            prior_literals/4,        % +Case, +Prior, +Example, -Literals
            prior_contradicted/4,    % +Case, +Prior, +Example, -Literals
            prior_kinds/3            % +Case, +Literals, -KindLiterals
          ]).

/** <module> Transfer: a learned model of one case as the prior of another

A prior is the learned model of an earlier run (its model.pl, model_file.pl writes it):

    prior(PriorCase, HS, HG)

with the two boundary clauses of its version space. What it says about a new case is
only what the ontology maps: a literal of the prior's h_g (one the physics showed
necessary there) transfers to the new case when both cases declare its predicate with
the same meaning and roles:

  - a structural literal (structural_predicate(Class, Name/Arity) of a tool kind) when
    both cases' tool classes are the same hierarchy (case_tool_class/2: the rake and
    the hook are both hook_like, ontology/kinds/hook_like.pl);
  - a spatial literal when both cases declare a spatial_definition/4 with the same
    template, roles included (behind(tool, target); its geometry is each case's own),
    or templates with the same roles to which both cases give the same meaning with
    the optional hook spatial_meaning(?Case, ?Template, ?Meaning) (a prong turned down
    and a blade upright are both the working part across the pull's path); the
    literal then takes the new case's name.

The roles map through the version space's head, tool_pose(Tool, Target, Context): the
prior's head variables are bound to the new example's, so a literal transfers only as
the very literal of the new demonstration (handle_length(T, medium) does not transfer
to a demonstration whose tool has handle_length(T, long)). Task literals (which do not
name the tool) and the new case's untestable literals never transfer: no trial could
confirm or contradict them. No name of a case, class or predicate is written here: the
mapping is what the two cases' ontologies declare.

The version space then starts with the transferred literals as the prior's
predictions, open (version_space:vs_init_prior/3): trusted only as far as the trials
confirm them. A spatial literal (a relation the two cases give the same meaning) is
settled by the first success that satisfies it, and the stop is then certified
relative to it; a structural literal (a property of the demonstrated tool) is tested
like any unknown literal, only likelier necessary; a success that violates either drops
it (the physics contradicted the prior), and a failure is learned from as without a
prior.
*/

:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(readutil), [read_file_to_string/3]).
:- use_module(text_terms, [text_terms/2]).
:- use_module(case, [must_be_case/1, case_answer/1, case_holds/1, class_holds/1,
                      case_knowledge/2]).

%!  read_prior(+File, -Prior) is det.
%
%   Prior is prior(Case, HS, HG) from the learned_hypothesis(Case, hs|hg, Clause)
%   terms of the model file File (model_file.pl), read as read_prior_text/3 reads
%   its text. Raises existence_error(file, File) for a missing file.

read_prior(File, Prior) :-
    must_be(atom, File),
    (   exists_file(File)
    ->  true
    ;   existence_error(file, File)
    ),
    read_file_to_string(File, Text, [encoding(utf8)]),
    read_prior_text(Text, File, Prior).

%!  read_prior_text(+Text, +File, -Prior) is det.
%
%   Prior is prior(Case, HS, HG) from the learned_hypothesis(Case, hs|hg, Clause)
%   terms of Text, the contents of the model file File. The terms are read as data
%   (text_terms:text_terms/2: never called, never deeper than term_depth_max/1).
%   Raises the reader's syntax_error, representation_error(term_depth(Max)) for a
%   term nested too deep, and domain_error(learned_model_file, File) when Text has no
%   two bounds of one case.

read_prior_text(Text, File, prior(Case, HS, HG)) :-
    text_terms(Text, Terms),
    (   memberchk(learned_hypothesis(Case, hs, HS), Terms),
        memberchk(learned_hypothesis(Case, hg, HG), Terms),
        atom(Case)
    ->  true
    ;   domain_error(learned_model_file, File)
    ).

%!  prior_shared(+Case, +Prior, -Shared:list) is det.
%
%   Shared are the literals of the prior's h_g whose predicate the ontology maps from
%   the prior's case to Case (see the module comment), in Case's vocabulary.
%   [] means the prior says nothing about Case. Raises existence_error(case, C) when
%   the prior's case is not in the loaded ontology.

prior_shared(Case, prior(PCase, _HS, HG), Shared) :-
    must_be_case(Case),
    must_be_case(PCase),
    body_list_(HG, _, Body),
    foldl(transfer_literal_(PCase, Case), Body, Shared, []).

transfer_literal_(PCase, Case, L, Out0, Out) :-
    (   transferable_(PCase, Case, L, L1)
    ->  Out0 = [L1|Out]
    ;   Out0 = Out
    ).

%!  prior_literals(+Case, +Prior, +Example, -Literals:list) is det.
%
%   Literals are the body literals of Example (the ground first positive of the new
%   case's version space, tool_pose(Tool, Target, Context) :- ...) that the prior's
%   h_g names once its head is bound to Example's and that prior_shared/3 maps: the
%   literals the version space takes from the prior.

prior_literals(Case, Prior, Example, Literals) :-
    mapped_literals_(Case, Prior, Example, in_body_, Literals).

%!  prior_contradicted(+Case, +Prior, +Example, -Literals:list) is det.
%
%   Literals are the mapped literals of the prior's h_g (prior_shared/3), with its head
%   bound to Example's, that the demonstration Example violates: ground and not in its
%   body (a prior's handle_length(T, long) against a demonstration whose tool's
%   handle is medium). The demonstration succeeded without them, so the physics contradicts the
%   prior there: they are not taken.

prior_contradicted(Case, Prior, Example, Literals) :-
    mapped_literals_(Case, Prior, Example, violated_, Literals).

%   mapped_literals_(+Case, +Prior, +Example, +Test, -Literals) is det.
%
%   The mapped literals of the prior's h_g (prior_shared/3), its head bound to
%   Example's, for which call(Test, Body, Literal) holds on Example's body; [] when the
%   two heads differ.

mapped_literals_(Case, Prior, Example, Test, Literals) :-
    prior_shared(Case, Prior, Shared0),
    Prior = prior(_, _, HG),
    copy_term(HG-Shared0, HG1-Shared),
    body_list_(HG1, PHead, _),
    body_list_(Example, Head, Body),
    (   functor(PHead, N, A),
        functor(Head, N, A)
    ->  PHead = Head,
        arg(1, Head, Tool),
        case_answer(untestable_literals(Case, Untestable)),
        include(testable_about_(Tool, Untestable), Shared, Shared1),
        include(call(Test, Body), Shared1, Literals0),
        list_to_set(Literals0, Literals)
    ;   Literals = []
    ).

%!  prior_kinds(+Case, +Literals:list, -KindLiterals:list) is det.
%
%   KindLiterals pairs each literal of Literals (in Case's vocabulary, as
%   prior_literals/4 gives them) with its kind: spatial when Case declares a
%   spatial_definition/4 of its name and arity, else structural.

prior_kinds(Case, Lits, Pairs) :-
    must_be_case(Case),
    maplist(prior_kind_(Case), Lits, Pairs).

prior_kind_(Case, L, Kind-L) :-
    (   compound(L),
        functor(L, N, A),
        case_holds(spatial_definition(Case, T, _, _)),
        functor(T, N, A)
    ->  Kind = spatial
    ;   Kind = structural
    ).

%   A literal a trial can test: about the tool (a task literal, which does not name
%   it, is what every trial of the case has) and none of the case's untestable ones
%   (in_tube(T, C): the tool in the tube): no trial could confirm or contradict the
%   others, so they are not taken.
testable_about_(Tool, Untestable, L) :-
    L =.. [_|Args],
    once(( member(X, Args), X == Tool )),
    \+ ( member(Pattern, Untestable), subsumes_term(Pattern, L) ).

violated_(Body, L) :-
    ground(L),
    \+ memberchk(L, Body).

in_body_(Body, L) :-
    ground(L),
    memberchk(L, Body).

transferable_(PCase, Case, L, L1) :-
    compound(L),
    L \= in_range(_, _, _),
    functor(L, N, A),
    (   structural_(PCase, N/A),
        structural_(Case, N/A),
        case_answer(case_tool_class(PCase, Class)),
        case_answer(case_tool_class(Case, Class))
    ->  L1 = L
    ;   case_holds(spatial_definition(PCase, T, _, _)),
        functor(T, N, A),
        case_holds(spatial_definition(Case, T2, _, _)),
        same_meaning_(PCase, T, Case, T2)
    ->  functor(T2, N2, _),
        L =.. [_|Args],
        L1 =.. [N2|Args]
    ).

%   Two spatial templates mean the same when they are the same template (name and
%   roles) or when both cases give them the same spatial_meaning/3 with the same roles.
same_meaning_(_, T, _, T2) :-
    T2 =@= T,
    !.
same_meaning_(PCase, T, Case, T2) :-
    T =.. [_|Roles],
    T2 =.. [_|Roles2],
    Roles == Roles2,
    case_knowledge(PCase, spatial_meaning(PCase, T0, M)),
    T0 =@= T,
    case_knowledge(Case, spatial_meaning(Case, T1, M1)),
    T1 =@= T2,
    M1 =@= M,
    !.

structural_(Case, PI) :-
    case_answer(case_tool_class(Case, Class)),
    once(class_holds(structural_predicate(Class, PI))).

body_list_((H :- B), H, L) :- !,
    conj_list_(B, L).
body_list_(H, H, []).

conj_list_(true, []) :- !.
conj_list_((A, B), [A|L]) :- !,
    conj_list_(B, L).
conj_list_(A, [A]).
