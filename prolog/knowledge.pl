:- module(knowledge,
          [ load_ontology/1,          % +File
            load_ontology_files/1,    % +Files
            load_default_ontology/0,
            kb_holds/1,               % :Goal
            kb_prove/2,               % +Goal, +Facts
            kb_clause/2,              % ?Head, ?Body
            kb_assert_facts/1,        % +Facts
            kb_retract_facts/1,       % +Pattern
            kb_loaded_files/1,        % -Files
            kb_assert_learned/1,      % +Term
            learned_model/4,          % ?Task, ?Action, ?Pre, ?Eff
            learned_hypothesis/3,     % ?Task, ?Bound, ?Clause
            kb_reset/0,
            kb_reset_all/0
          ]).

/** <module> The knowledge base: ontology, world facts and what is learned

This is the one module that owns the dynamic database (docs/architecture.md).  Knowledge
lives in the module `kb`, kept apart from this module's own predicates, whose only
default import is `system`:

  - the *ontology*: plain Prolog files (the .pl files of ontology/ and its
    subdirectories, no directives) read clause by clause by load_ontology/1 and
    asserted into `kb`;
  - *world facts*: ground facts added by kb_assert_facts/1 (perception's primitive
    facts, a catalogue, a learned model), removed by kb_retract_facts/1 or kb_reset/0.

Loading checks what SWI-Prolog would only print: a syntax error raises
error(syntax_error(Message), file(File, Line, LinePos, CharNo)); a clause whose body
calls a predicate that is neither defined by the loaded knowledge, nor declared as a
primitive fact predicate (`primitive_predicate(Name/Arity)` facts of the ontology), nor
built in, raises error(existence_error(procedure, Name/Arity), file(File, Line, -1, 0)).
A load is all or nothing: nothing is asserted unless every file of the call is clean.
Reloading a file replaces its clauses.

The ontology's predicates answer queries against the asserted world facts
(kb_holds/1), or against a list of facts handed over in an argument (kb_prove/2), so
that callers keep their state in arguments.
*/

:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).

%   ontology_clause_(File, Ref): Ref is a clause of kb asserted from File.
:- dynamic ontology_clause_/2.
%   loaded_file_(File): File's clauses are in kb, in load order.
:- dynamic loaded_file_/1.
%   world_fact_(Ref): Ref is a world fact asserted by kb_assert_facts/1.
:- dynamic world_fact_/1.
:- dynamic learned_model_/4.
:- dynamic learned_hypothesis_/3.

:- initialization(init_kb_module_).

init_kb_module_ :-
    set_module(kb:base(system)),
    set_module(kb:class(user)),
    kb:use_module(library(lists)).

%!  load_ontology(+File) is det.
%
%   Read the plain Prolog file File (a path or an alias such as
%   ontology(kinds/hook_like)) and assert its clauses into the knowledge base.  Calls in
%   clause bodies are checked against the whole knowledge base after the load.
%
%   @error existence_error(source_sink, File) if File does not exist.
%   @error syntax_error(Message) with context file(Path, Line, LinePos, CharNo).
%   @error existence_error(procedure, Name/Arity) with context file(Path, Line, -1, 0)
%          for a call to an unknown predicate.
%   @error domain_error(ontology_clause, Term) for a directive (ontology files are data).
%
%   ==
%   ?- load_ontology(ontology(ranges)), kb_holds(qualitative_value(handle_length, 0.3, V)).
%   V = medium.
%   ==
load_ontology(File) :-
    load_ontology_files([File]).

%!  load_ontology_files(+Files:list) is det.
%
%   Load every file of Files as load_ontology/1 does, checking the calls once all of
%   them are read, so that files may refer to each other.  Nothing is asserted if any
%   file is missing or wrong.
%
%   ==
%   ?- load_ontology_files([ontology(ranges), ontology(world), ontology(kinds/hook_like)]).
%   true.
%   ==
load_ontology_files(Files) :-
    must_be(list, Files),
    maplist(resolve_file_, Files, Paths),
    foldl(read_file_clauses_, Paths, Items, []),
    check_calls_(Items),
    maplist(unload_file_, Paths),
    maplist(assert_item_, Items),
    forall(member(P, Paths), assertz(loaded_file_(P))),
    declare_primitives_.

%!  load_default_ontology is det.
%
%   Load every `.pl` file of the ontology directory (the `ontology` file search path
%   set by prolog/creative.pl, else ../ontology relative to this module) and of its
%   subdirectories (cases/, kinds/, ...), in a fixed order: a directory's files in name
%   order, then each subdirectory in name order, depth first.  The order is the order of
%   the clauses of a predicate that several files define.
%
%   ==
%   ?- load_default_ontology, kb_holds(subclass_of(hook, C)).
%   C = hook_like.
%   ==
load_default_ontology :-
    ontology_directory_(Dir),
    ontology_files_(Dir, Paths),
    load_ontology_files(Paths).

%   ontology_files_(+Dir, -Paths): the .pl files of Dir in name order, then those of
%   its subdirectories (hidden ones left out), each in turn.
ontology_files_(Dir, Paths) :-
    directory_files(Dir, Entries),
    msort(Entries, Sorted),
    findall(Path,
            ( member(E, Sorted),
              file_name_extension(_, pl, E),
              directory_file_path(Dir, E, Path),
              exists_file(Path)
            ),
            Files),
    findall(Sub,
            ( member(E, Sorted),
              \+ sub_atom(E, 0, _, _, '.'),
              directory_file_path(Dir, E, Sub),
              exists_directory(Sub)
            ),
            Subs),
    maplist(ontology_files_, Subs, SubPaths),
    append([Files|SubPaths], Paths).

ontology_directory_(Dir) :-
    (   absolute_file_name(ontology(.), Dir0,
                           [file_type(directory), file_errors(fail)])
    ->  Dir = Dir0
    ;   module_property(knowledge, file(Here)),
        file_directory_name(Here, PrologDir),
        file_directory_name(PrologDir, Root),
        directory_file_path(Root, ontology, Dir)
    ).

resolve_file_(File, Path) :-
    must_be(ground, File),
    (   absolute_file_name(File, Path,
                           [file_type(prolog), access(read), file_errors(fail)])
    ->  true
    ;   existence_error(source_sink, File)
    ).

%   read_file_clauses_(+Path, -Items, ?Tail): Items are item(Clause, Path, Line).
read_file_clauses_(Path, Items, Tail) :-
    setup_call_cleanup(
        open(Path, read, In),
        read_clauses_(In, Path, Items, Tail),
        close(In)).

read_clauses_(In, Path, Items, Tail) :-
    catch(read_term(In, Term, [term_position(Pos), syntax_errors(error)]),
          error(syntax_error(Message), Where),
          syntax_error_in_file_(Path, Message, Where)),
    (   Term == end_of_file
    ->  Items = Tail
    ;   stream_position_data(line_count, Pos, Line),
        check_clause_(Term, Path, Line),
        Items = [item(Term, Path, Line)|Items1],
        read_clauses_(In, Path, Items1, Tail)
    ).

syntax_error_in_file_(Path, Message, Where) :-
    (   Where = file(_, Line, LinePos, CharNo)
    ->  true
    ;   Where = stream(_, Line, LinePos, CharNo)
    ->  true
    ;   Line = -1,
        LinePos = -1,
        CharNo = 0
    ),
    throw(error(syntax_error(Message), file(Path, Line, LinePos, CharNo))).

check_clause_(Term, Path, Line) :-
    (   Term = (:- _)
    ->  throw(error(domain_error(ontology_clause, Term), file(Path, Line, -1, 0)))
    ;   Term = (Head :- _)
    ->  check_head_(Head, Path, Line)
    ;   check_head_(Term, Path, Line)
    ).

check_head_(Head, Path, Line) :-
    (   \+ callable(Head)
    ->  throw(error(type_error(callable, Head), file(Path, Line, -1, 0)))
    ;   predicate_property(system:Head, defined)
    ->  functor(Head, N, A),
        throw(error(permission_error(modify, static_procedure, N/A),
                    file(Path, Line, -1, 0)))
    ;   true
    ).

%   check_calls_(+Items): every called predicate is known.
check_calls_(Items) :-
    findall(N/A, ( member(item(C, _, _), Items), clause_head_(C, H), functor(H, N, A) ),
            NewDefined0),
    findall(PI, member(item(primitive_predicate(PI), _, _), Items), NewPrimitive),
    append(NewDefined0, NewPrimitive, NewDefined1),
    sort(NewDefined1, NewDefined),
    forall(member(item(C, Path, Line), Items),
           ( clause_body_(C, Body),
             check_body_(Body, NewDefined, Path, Line) )).

clause_head_((H :- _), H) :- !.
clause_head_(H, H).

clause_body_((_ :- B), B) :- !.
clause_body_(_, true).

check_body_(G, _, _, _) :-
    var(G),
    !.
check_body_(G, Defined, Path, Line) :-
    control_(G, Subgoals),
    !,
    forall(member(S, Subgoals), check_body_(S, Defined, Path, Line)).
check_body_(G, Defined, Path, Line) :-
    functor(G, N, A),
    (   known_predicate_(N/A, G, Defined)
    ->  true
    ;   throw(error(existence_error(procedure, N/A), file(Path, Line, -1, 0)))
    ).

%   control_(+Goal, -Subgoals): Goal is a control construct or meta-call over Subgoals.
control_((A, B), [A, B]).
control_((A ; B), [A, B]).
control_((A -> B), [A, B]).
control_((A *-> B), [A, B]).
control_(\+ A, [A]).
control_(call(A), [A]).
control_(once(A), [A]).
control_(ignore(A), [A]).
control_(forall(A, B), [A, B]).
control_(findall(_, A, _), [A]).
control_(aggregate_all(_, A, _), [A]).

known_predicate_(PI, _, Defined) :-
    memberchk(PI, Defined),
    !.
known_predicate_(N/A, _, _) :-
    current_predicate(kb:N/A),
    functor(H, N, A),
    \+ predicate_property(kb:H, imported_from(_)),
    !.
known_predicate_(PI, _, _) :-
    kb_primitive_(PI),
    !.
known_predicate_(_, G, _) :-
    predicate_property(kb:G, defined).

kb_primitive_(PI) :-
    current_predicate(kb:primitive_predicate/1),
    kb:primitive_predicate(PI).

unload_file_(Path) :-
    forall(retract(ontology_clause_(Path, Ref)), erase(Ref)),
    retractall(loaded_file_(Path)).

assert_item_(item(Clause, Path, _Line)) :-
    assertz(kb:Clause, Ref),
    assertz(ontology_clause_(Path, Ref)).

%   Primitive fact predicates exist (dynamic) before any world fact is asserted, so that
%   asking about them fails instead of raising.
declare_primitives_ :-
    forall(kb_primitive_(N/A), dynamic(kb:N/A)).

%!  kb_loaded_files(-Files:list) is det.
%
%   Files are the absolute paths of the loaded ontology files, in load order.
%
%   ==
%   ?- load_ontology(ontology(ranges)), kb_loaded_files(Fs).
%   Fs = ['/work/main/ontology/ranges.pl'].
%   ==
kb_loaded_files(Files) :-
    findall(F, loaded_file_(F), Files).

%!  kb_holds(:Goal) is nondet.
%
%   Call Goal in the knowledge base (ontology plus asserted world facts).
%
%   ==
%   ?- load_default_ontology, kb_assert_facts([object_kind(h1, hook), handle_length_m(h1, 0.3)]),
%      kb_holds(handle_length(h1, V)).
%   V = medium.
%   ==
kb_holds(Goal) :-
    must_be(callable, Goal),
    call(kb:Goal).

%!  kb_clause(?Head, ?Body) is nondet.
%
%   Head :- Body is a clause of the knowledge base (Body = true for a fact), in the
%   order the clauses were loaded.
%
%   ==
%   ?- load_default_ontology, kb_clause(any_length(X), B).
%   B = handle_length(X, medium) ;
%   B = handle_length(X, long) ;
%   B = handle_length(X, short).
%   ==
kb_clause(Head, Body) :-
    must_be(callable, Head),
    functor(Head, N, A),
    current_predicate(kb:N/A),
    \+ predicate_property(kb:Head, imported_from(_)),
    clause(kb:Head, Body).

%!  kb_prove(+Goal, +Facts:list) is nondet.
%
%   Prove Goal from the ontology's rules, taking primitive facts (those of the ontology's
%   primitive_predicate/1 declarations) from the list Facts instead of the database.
%   Rules are interpreted clause by clause; built-in goals are called.
%
%   ==
%   ?- load_default_ontology,
%      kb_prove(handle_length(h1, V), [object_kind(h1, hook), handle_length_m(h1, 0.5)]).
%   V = long.
%   ==
kb_prove(Goal, Facts) :-
    must_be(callable, Goal),
    must_be(list, Facts),
    prove_(Goal, Facts).

prove_(G, _) :-
    var(G),
    !,
    instantiation_error(G).
prove_(true, _) :- !.
prove_((A, B), Fs) :- !,
    prove_(A, Fs),
    prove_(B, Fs).
prove_((C -> T ; E), Fs) :- !,
    (   prove_(C, Fs)
    ->  prove_(T, Fs)
    ;   prove_(E, Fs)
    ).
prove_((C *-> T ; E), Fs) :- !,
    (   prove_(C, Fs)
    *-> prove_(T, Fs)
    ;   prove_(E, Fs)
    ).
prove_((A ; B), Fs) :- !,
    (   prove_(A, Fs)
    ;   prove_(B, Fs)
    ).
prove_((C -> T), Fs) :- !,
    (   prove_(C, Fs)
    ->  prove_(T, Fs)
    ).
prove_(\+ G, Fs) :- !,
    \+ prove_(G, Fs).
prove_(call(G), Fs) :- !,
    prove_(G, Fs).
prove_(once(G), Fs) :- !,
    once(prove_(G, Fs)).
prove_(findall(T, G, L), Fs) :- !,
    findall(T, prove_(G, Fs), L).
prove_(forall(C, A), Fs) :- !,
    forall(prove_(C, Fs), prove_(A, Fs)).
prove_(G, Fs) :-
    functor(G, N, A),
    (   kb_primitive_(N/A)
    ->  member(G, Fs)
    ;   current_predicate(kb:N/A),
        \+ predicate_property(kb:G, imported_from(_))
    ->  clause(kb:G, Body),
        prove_(Body, Fs)
    ;   call(kb:G)
    ).

%!  kb_assert_facts(+Facts:list) is det.
%
%   Add the ground facts Facts to the knowledge base as world facts (removed again by
%   kb_retract_facts/1, kb_reset/0).
%
%   @error instantiation_error or type_error(callable, F) for a fact that is not ground
%          and callable; type_error(fact, (H :- B)) for a clause with a body.
%
%   ==
%   ?- kb_assert_facts([pose(cube1, 0.9, 0.0, -0.05, 0.0)]), kb_holds(pose(cube1, X, _, _, _)).
%   X = 0.9.
%   ==
kb_assert_facts(Facts) :-
    must_be(list, Facts),
    maplist(check_fact_, Facts),
    forall(member(F, Facts),
           ( assertz(kb:F, Ref),
             assertz(world_fact_(Ref)) )).

check_fact_(F) :-
    must_be(callable, F),
    must_be(ground, F),
    (   F = (_ :- _)
    ->  type_error(fact, F)
    ;   control_(F, _)
    ->  type_error(fact, F)
    ;   predicate_property(system:F, defined)
    ->  functor(F, N, A),
        permission_error(modify, static_procedure, N/A)
    ;   true
    ).

%!  kb_retract_facts(+Pattern) is det.
%
%   Remove every world fact that unifies with Pattern.  Ontology clauses are never
%   removed.
%
%   ==
%   ?- kb_assert_facts([pose(cube1, 0.9, 0, 0, 0)]), kb_retract_facts(pose(cube1, _, _, _, _)).
%   true.
%   ==
kb_retract_facts(Pattern) :-
    must_be(callable, Pattern),
    forall(( world_fact_(Ref),
             clause(kb:Fact, true, Ref),
             \+ Fact \= Pattern ),
           ( erase(Ref),
             retract(world_fact_(Ref)) )).

%!  kb_reset is det.
%
%   Remove every world fact: the knowledge base holds the loaded ontology only.
%
%   ==
%   ?- kb_reset.
%   true.
%   ==
kb_reset :-
    forall(retract(world_fact_(Ref)), erase(Ref)),
    retractall(learned_model_(_, _, _, _)),
    retractall(learned_hypothesis_(_, _, _)).

%!  kb_assert_learned(+Term) is det.
%
%   Add what a run learned: Term is learned_model(Task, Action, Pre, Eff) or
%   learned_hypothesis(Task, Bound, Clause) (Bound is hs or hg), as written in a run's
%   model.pl (model_file:load_model_file/1 reads it). Raises a domain_error for any
%   other term. Removed by kb_reset/0.
%
%   ==
%   ?- kb_assert_learned(learned_model(hook, pull_out(T, C, X), [hook(T)], [])),
%      learned_model(hook, A, P, _).
%   A = pull_out(_, _, _), P = [hook(_)].
%   ==
kb_assert_learned(Term) :-
    (   Term = learned_model(Task, Action, Pre, Eff)
    ->  must_be(ground, Task),
        must_be(callable, Action),
        must_be(list, Pre),
        must_be(list, Eff),
        assertz(learned_model_(Task, Action, Pre, Eff))
    ;   Term = learned_hypothesis(Task, Bound, Clause)
    ->  must_be(atom, Task),
        must_be(oneof([hs, hg]), Bound),
        assertz(learned_hypothesis_(Task, Bound, Clause))
    ;   domain_error(learned_term, Term)
    ).

%!  learned_model(?Task, ?Action, ?Pre, ?Eff) is nondet.
%
%   A learned action model: Task (hook, wedge), the action term with its parameters,
%   its precondition (the learned h_g, plus the skill's own preconditions) and effects
%   (add(L) and del(L) terms). Empty until a run's model.pl is loaded.
%
%   ==
%   ?- load_model_file('runs/hook-.../model.pl'), learned_model(hook, A, Pre, _).
%   A = pull_out(_A, _B, _C), Pre = [holding(_A), hook(_A), ...].
%   ==
learned_model(Task, Action, Pre, Eff) :-
    learned_model_(Task, Action, Pre, Eff).

%!  learned_hypothesis(?Task, ?Bound, ?Clause) is nondet.
%
%   The final version-space boundaries of a run: Bound hs (most specific) or hg (most
%   general), Clause a tool_pose(Tool, Target, Context) :- Body clause.
learned_hypothesis(Task, Bound, Clause) :-
    learned_hypothesis_(Task, Bound, Clause).

%!  kb_reset_all is det.
%
%   Empty the knowledge base: world facts, ontology clauses and the record of loaded
%   files.
%
%   ==
%   ?- kb_reset_all, kb_loaded_files(Fs).
%   Fs = [].
%   ==
kb_reset_all :-
    kb_reset,
    retractall(ontology_clause_(_, _)),
    retractall(loaded_file_(_)),
    forall(( current_predicate(kb:N/A),
             functor(H, N, A),
             \+ predicate_property(kb:H, imported_from(_)),
             predicate_property(kb:H, dynamic)
           ),
           abolish(kb:N/A)).
