:- module(pddl,
          [ pddl_domain/3,              % +DomainName, +Models, -Text
            pddl_domain/4,              % +DomainName, +Models, +Options, -Text
            pddl_problem/6,             % +ProblemName, +DomainName, +Objects, +State, +Goal, -Text
            pddl_plan/2,                % +Steps, -Text
            pddl_write_domain/3,        % +File, +DomainName, +Models
            pddl_write_problem/6,       % +File, +ProblemName, +DomainName, +Objects, +State, +Goal
            pddl_write_files/6          % +DomainFile, +ProblemFile, +Models, +State, +Goal, +Options
          ]).

/** <module> Action models, states and goals as PDDL text

The domain is STRIPS with typing; `:negative-preconditions` is declared only when a
model's precondition holds a `not(L)` literal.  The models are compiled first
(action_model:action_models_compile/2), so the motion skills (position_tool, place)
are written as ordinary actions whose add effects are the spatial literals the
learned models require (e.g. position_tool adds in_tube, behind, centred_on and
hook_down of its tool); action names are the Prolog planner's, so a plan from
planner:plan/5 is a plan of the PDDL domain.

Names.  Predicates, actions and objects keep their Prolog names, which must be PDDL
names (a lower-case letter, then lower-case letters, digits, `_` or `-`); the
predicate `object/1` (a wedge-case structural literal) is written `is_object`, since
`object` is PDDL's root type.  Parameter types map to PDDL types: tool ->
`tool_object` (the predicate tool/1 keeps the name `tool`), target -> `target`,
site -> `site`; qualitative values (medium, right, ...) are of type `value`.  Every
predicate argument is declared of type `object`.  Parameters are written `?tool`,
`?target`, `?site` (with a number when a type repeats).

Qualitative values that occur in the models are domain `:constants`; the problem
declares every other constant of its state and goal as an object.
*/

:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(option)).
:- use_module(library(error)).
:- use_module(action_model).

%!  pddl_domain(+DomainName, +Models, -Text) is det.
%
%   Same as pddl_domain/4 with no options.
%
%       ?- innate_action_models(hook, [P|_]), pddl_domain(d, [P], T),
%          sub_string(T, _, _, _, "(:action pick_up").
%       true.

pddl_domain(DomainName, Models, Text) :-
    pddl_domain(DomainName, Models, [], Text).

%!  pddl_domain(+DomainName, +Models, +Options, -Text) is det.
%
%   Text is a PDDL domain (a string) with one action per compiled model of Models.
%   Options: extra_literals(Ls): also declare the predicates of the literals Ls
%   (e.g. the state's and the goal's).
%
%       ?- pddl_domain(d, [action_model(a, [X-tool], [p(X)], [q(X)], [])],
%                      [extra_literals([r(x, y)])], T),
%          sub_string(T, _, _, _, "(r ?a1 - object ?a2 - object)").
%       true.
%
%   @error domain_error(pddl_name, X) if a name is not a PDDL name.
%   @error domain_error(pddl_strips_literal(Action), L) if a literal of an action
%          has a variable that is not a parameter.

pddl_domain(DomainName, Models, Options, Text) :-
    must_be_pddl_name_(DomainName),
    must_be(list, Options),
    option(extra_literals(Extra), Options, []),
    must_be(list, Extra),
    action_models_compile(Models, Actions),
    maplist(action_literals_, Actions, LiteralLists),
    append([Extra|LiteralLists], Literals),
    predicate_signatures_(Literals, Signatures),
    domain_constants_(Actions, Constants),
    (   member(A, Actions), A = action_model(_, _, Pre, _, _), memberchk(not(_), Pre)
    ->  Requirements = ':strips :typing :negative-preconditions'
    ;   Requirements = ':strips :typing'
    ),
    with_output_to(string(Text),
                   write_domain_(DomainName, Requirements, Constants, Signatures,
                                 Actions)).

action_literals_(action_model(_, _, Pre, Add, Del), Literals) :-
    maplist(strip_not_, Pre, Pre1),
    append([Pre1, Add, Del], Literals).

strip_not_(L0, L) :-
    (   L0 = not(L1)
    ->  L = L1
    ;   L = L0
    ).

predicate_signatures_(Literals, Signatures) :-
    findall(F/N, ( member(L, Literals), functor(L, F, N) ), Sigs0),
    sort(Sigs0, Signatures).

domain_constants_(Actions, Constants) :-
    findall(C, ( member(action_model(_, _, Pre, Add, Del), Actions),
                 append([Pre, Add, Del], Ls),
                 member(L0, Ls),
                 strip_not_(L0, L),
                 L =.. [_|Args],
                 member(C, Args),
                 atom(C)
               ),
            Cs0),
    sort(Cs0, Constants).

write_domain_(Name, Requirements, Constants, Signatures, Actions) :-
    format("(define (domain ~w)~n", [Name]),
    format("  (:requirements ~w)~n", [Requirements]),
    format("  (:types tool_object target site value - object)~n"),
    (   Constants == []
    ->  true
    ;   maplist(must_be_pddl_name_, Constants),
        atomic_list_concat(Constants, ' ', CText),
        format("  (:constants ~w - value)~n", [CText])
    ),
    format("  (:predicates~n"),
    forall(member(F/N, Signatures), write_signature_(F, N)),
    format("  )~n"),
    forall(member(A, Actions), write_action_(A)),
    format(")~n").

write_signature_(F, N) :-
    pddl_predicate_name_(F, PF),
    numlist_(N, Is),
    maplist([I, S]>>format(atom(S), " ?a~w - object", [I]), Is, Ss),
    atomic_list_concat(Ss, ArgText),
    format("    (~w~w)~n", [PF, ArgText]).

numlist_(N, Is) :-
    (   N =:= 0
    ->  Is = []
    ;   numlist(1, N, Is)
    ).

write_action_(action_model(Name, Params, Pre, Add, Del)) :-
    must_be_pddl_name_(Name),
    copy_term(Params-Pre-Add-Del, Params1-Pre1-Add1-Del1),
    name_params_(Params1),
    append([Pre1, Add1, Del1], Ls),
    (   member(L, Ls), \+ ground(L)
    ->  domain_error(pddl_strips_literal(Name), L)
    ;   true
    ),
    maplist([V-T, S]>>( pddl_type_(T, PT), format(atom(S), "~w - ~w", [V, PT]) ),
            Params1, ParamTexts),
    atomic_list_concat(ParamTexts, ' ', ParamText),
    format("  (:action ~w~n", [Name]),
    format("    :parameters (~w)~n", [ParamText]),
    conjunction_text_(Pre1, PreText),
    format("    :precondition ~w~n", [PreText]),
    maplist([L, not(L)]>>true, Del1, NotDel),
    append(Add1, NotDel, Effects),
    conjunction_text_(Effects, EffText),
    format("    :effect ~w)~n", [EffText]).

%   Bind each parameter variable to its PDDL variable name (an atom '?tool').
name_params_(Params) :-
    foldl(name_param_, Params, [], _).

name_param_(V-Type, Seen, [Type|Seen]) :-
    include(==(Type), Seen, Same),
    length(Same, K),
    (   K =:= 0
    ->  format(atom(Name), "?~w", [Type])
    ;   K1 is K + 1,
        format(atom(Name), "?~w~w", [Type, K1])
    ),
    V = Name.

pddl_type_(tool, tool_object).
pddl_type_(target, target).
pddl_type_(site, site).
pddl_type_(value, value).

conjunction_text_(Literals, Text) :-
    maplist(literal_text_, Literals, Texts),
    (   Texts == []
    ->  Text = "(and)"
    ;   atomic_list_concat(Texts, ' ', Inner),
        format(string(Text), "(and ~w)", [Inner])
    ).

literal_text_(L, Text) :-
    (   L = not(P)
    ->  literal_text_(P, PText),
        format(string(Text), "(not ~w)", [PText])
    ;   callable(L)
    ->  L =.. [F|Args],
        pddl_predicate_name_(F, PF),
        maplist(argument_text_, Args, ArgTexts),
        atomic_list_concat([PF|ArgTexts], ' ', Inner),
        format(string(Text), "(~w)", [Inner])
    ;   type_error(literal, L)
    ).

argument_text_(A, A) :-
    (   sub_atom(A, 0, 1, _, '?')
    ->  true
    ;   must_be_pddl_name_(A)
    ).

pddl_predicate_name_(F, PF) :-
    must_be_pddl_name_(F),
    (   reserved_name_(F)
    ->  atom_concat(is_, F, PF)
    ;   PF = F
    ).

reserved_name_(object).
reserved_name_(either).
reserved_name_(and).
reserved_name_(or).
reserved_name_(not).
reserved_name_(exists).
reserved_name_(forall).
reserved_name_(when).
reserved_name_(imply).

must_be_pddl_name_(X) :-
    (   atom(X),
        atom_codes(X, [C|Cs]),
        code_type(C, lower),
        forall(member(D, Cs), name_code_(D))
    ->  true
    ;   domain_error(pddl_name, X)
    ).

name_code_(D) :-
    (   code_type(D, lower)
    ;   code_type(D, digit)
    ;   D =:= 0'_
    ;   D =:= 0'-
    ),
    !.

%!  pddl_problem(+ProblemName, +DomainName, +Objects, +State, +Goal, -Text) is det.
%
%   Text is a PDDL problem (a string): Objects (a list of Name-Type, Type one of
%   tool, target, site, value) as :objects, the ground literals of State as :init
%   and those of Goal as the conjunctive :goal.
%
%       ?- pddl_problem(p, d, [h-tool], [on_table(h)], [holding(h)], T),
%          sub_string(T, _, _, _, "(:goal (and (holding h)))").
%       true.
%
%   @error type_error(ground_literal, L) if a literal is not ground.

pddl_problem(ProblemName, DomainName, Objects, State, Goal, Text) :-
    must_be_pddl_name_(ProblemName),
    must_be_pddl_name_(DomainName),
    must_be(list, Objects),
    must_be(list, State),
    must_be(list, Goal),
    maplist(must_be_ground_, State),
    maplist(must_be_ground_, Goal),
    maplist(object_text_, Objects, ObjectTexts),
    atomic_list_concat(ObjectTexts, ' ', ObjectText),
    maplist(literal_text_, State, InitTexts),
    conjunction_text_(Goal, GoalText),
    with_output_to(string(Text),
                   ( format("(define (problem ~w)~n", [ProblemName]),
                     format("  (:domain ~w)~n", [DomainName]),
                     format("  (:objects ~w)~n", [ObjectText]),
                     format("  (:init~n"),
                     forall(member(I, InitTexts), format("    ~w~n", [I])),
                     format("  )~n"),
                     format("  (:goal ~w)~n", [GoalText]),
                     format(")~n")
                   )).

must_be_ground_(L) :-
    (   ground(L), callable(L)
    ->  true
    ;   type_error(ground_literal, L)
    ).

object_text_(Object, Text) :-
    (   Object = Name-Type, pddl_type_(Type, PType)
    ->  must_be_pddl_name_(Name),
        format(atom(Text), "~w - ~w", [Name, PType])
    ;   domain_error(typed_object, Object)
    ).

%!  pddl_plan(+Steps, -Text) is det.
%
%   Text is the plan Steps (ground action terms) in the usual plan-file form, one
%   `(name arg ...)` per line.
%
%       ?- pddl_plan([pick_up(hook_a2)], T).
%       T = "(pick_up hook_a2)\n".

pddl_plan(Steps, Text) :-
    must_be(list, Steps),
    maplist(must_be_ground_, Steps),
    maplist(literal_text_, Steps, Lines),
    with_output_to(string(Text), forall(member(L, Lines), format("~w~n", [L]))).

%!  pddl_write_domain(+File, +DomainName, +Models) is det.
%
%   Write pddl_domain/3's text to File.

pddl_write_domain(File, DomainName, Models) :-
    pddl_domain(DomainName, Models, Text),
    write_text_(File, Text).

%!  pddl_write_problem(+File, +ProblemName, +DomainName, +Objects, +State, +Goal) is det.
%
%   Write pddl_problem/6's text to File.

pddl_write_problem(File, ProblemName, DomainName, Objects, State, Goal) :-
    pddl_problem(ProblemName, DomainName, Objects, State, Goal, Text),
    write_text_(File, Text).

write_text_(File, Text) :-
    must_be(atomic, File),
    setup_call_cleanup(open(File, write, Out, [encoding(utf8)]),
                       write(Out, Text),
                       close(Out)).

%!  pddl_write_files(+DomainFile, +ProblemFile, +Models, +State, +Goal, +Options) is det.
%
%   Write a matching domain and problem: the domain declares the predicates of
%   Models and Goal; the problem's :init keeps the literals of State whose predicate
%   the domain declares, and its objects are every constant of that init and Goal
%   (typed by action_model:action_objects/4) that is not a domain constant, plus the
%   objects(List) option.
%
%   Tool typing.  Every object of the whole State that can be a tool is of type
%   `tool_object`, whether or not the literal that says so is declared by the domain
%   (a learned h_g seldom keeps tool/1): with the option case(Case), an object of a
%   class literal of the case's tool hierarchy (action_model:case_tool_objects/3,
%   asked of the ontology); without it, a catalogued object
%   (action_model:catalogued_object/2: tool(X), object(X) in State).
%
%   Options: domain_name(N) (default `creative`), problem_name(N) (default `task`),
%   objects(List) (Name-Type, e.g. [floor1-site]; wins over inference), case(Case).
%
%       ?- innate_action_models(hook, Ms),
%          pddl_write_files('/tmp/d.pddl', '/tmp/p.pddl', Ms,
%                           [gripper_empty, on_table(h), tool(h)], [holding(h)], []).
%       true.

pddl_write_files(DomainFile, ProblemFile, Models, State, Goal, Options) :-
    must_be(list, Options),
    option(domain_name(DomainName), Options, creative),
    option(problem_name(ProblemName), Options, task),
    option(objects(Extra0), Options, []),
    must_be(list, Extra0),
    state_tools_(Options, State, Tools),
    pairs_keys(Extra0, ExtraNames),
    findall(T-tool, ( member(T, Tools), \+ memberchk(T, ExtraNames) ), ToolObjects),
    append(Extra0, ToolObjects, Extra),
    pddl_domain(DomainName, Models, [extra_literals(Goal)], DomainText),
    action_models_compile(Models, Actions),
    maplist(action_literals_, Actions, LiteralLists),
    append([Goal|LiteralLists], Literals),
    predicate_signatures_(Literals, Signatures),
    include(declared_(Signatures), State, Init),
    domain_constants_(Actions, Constants),
    append(Init, Goal, Used),
    action_objects(Models, Used, Extra, Objects0),
    exclude(constant_object_(Constants), Objects0, Objects),
    pddl_problem(ProblemName, DomainName, Objects, Init, Goal, ProblemText),
    write_text_(DomainFile, DomainText),
    write_text_(ProblemFile, ProblemText).

%   The objects of State that can be a tool (see pddl_write_files/6).
state_tools_(Options, State, Tools) :-
    (   option(case(Case), Options)
    ->  case_tool_objects(Case, State, Tools)
    ;   findall(X, ( member(L, State), catalogued_object(L, X) ), Xs),
        sort(Xs, Tools)
    ).

declared_(Signatures, L) :-
    functor(L, F, N),
    memberchk(F/N, Signatures).

constant_object_(Constants, Name-_) :-
    memberchk(Name, Constants).
