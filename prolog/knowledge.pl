:- module(knowledge,
          [ load_ontology/1,          % +File
            load_ontology_files/1,    % +Files
            load_default_ontology/0,
            shared_holds/1,           % :Goal
            shared_prove/2,           % +Goal, +Facts
            shared_clause/2,          % ?Head, ?Body
            ontology_clause/2,        % ?Head, ?Body
            kb_case_module/2,         % ?Case, ?Module
            kb_kind_module/2,         % ?Kind, ?Module
            kb_apparatus_module/2,    % ?Apparatus, ?Module
            kb_modules/1,             % -Modules
            kb_module_scope/2,        % +Module, -Scope
            kb_module_defines/2,      % +Module, +Name/Arity
            kb_module_holds/2,        % +Module, +Goal
            kb_module_clause/3,       % +Module, ?Head, ?Body
            kb_module_prove/3,        % +Module, +Goal, +Facts
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

This is the one module that owns the dynamic database (docs/architecture.md).  The
ontology is plain Prolog data (the .pl files of ontology/ and its subdirectories, no
directives), read clause by clause by load_ontology/1 and asserted into one module per
file's *role*, each kept apart from this module's own predicates:

  - a **case file**, one holding a fact case(Case), goes into the module
    `case_<Case>` (ontology/cases/hook.pl: `case_hook`);
  - a **kind file**, one holding a fact kind(Kind), goes into `kind_<Kind>`
    (ontology/kinds/hook_like.pl: `kind_hook_like`);
  - an **apparatus file**, one holding a fact apparatus(Apparatus), goes into
    `apparatus_<Apparatus>` (ontology/apparatus/tube.pl: `apparatus_tube`): the
    knowledge of a piece of the world that several cases share (the tube, its
    perception, its task literals, its geometry), written once;
  - every other file is **shared** knowledge and goes into the module `kb` (ranges,
    replacement operators, the robot's own skills, the world frame).

A case module's default import modules are its kind's module (the kind whose hierarchy
holds the class its case_tool_class/2 fact names: the one with a subclass_of(Class, _)
fact, whatever the kind's name), then the modules of the apparatus it names by
case_apparatus/2 facts (in their order), then `kb`; a kind module's and an apparatus
module's is `kb`; `kb`'s is `system`.  So a case's rules see its own predicates, its
kind's, its apparatus' and the shared ones, and two cases may define the same helper
predicate, each seeing its own.  An apparatus clause whose first argument is a
variable answers a hook for every case that uses the apparatus.  World facts
(kb_assert_facts/1: perception's primitive facts, a catalogue) live in `kb`, seen by
every case.  The engine reads a case's knowledge through prolog/case.pl, which names
the case (kb_case_module/2) and raises when the case does not answer; the shared
readers shared_holds/1, shared_clause/2 and shared_prove/2 read `kb` only.

Loading checks what SWI-Prolog would only print: a syntax error raises
error(syntax_error(Message), file(File, Line, LinePos, CharNo)); a clause whose body
calls a predicate that is neither defined in the file's module or a module it sees, nor
declared as a primitive fact predicate (`primitive_predicate(Name/Arity)` facts of the
ontology), nor built in, raises error(existence_error(procedure, Name/Arity),
file(File, Line, -1, 0)).  A shared file's bodies may name any module's predicates
(the replacement operators name the kinds' properties; they are read as data).  A load
is all or nothing: nothing is asserted unless every file of the call is clean.
Reloading a file replaces its clauses.

Rules are called in their module (kb_module_holds/2), or proved against a list of
facts handed over in an argument (kb_module_prove/3), so that callers keep their state
in arguments.
*/

:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).

%   ontology_clause_(File, Ref): Ref is an ontology clause asserted from File.
:- dynamic ontology_clause_/2.
%   loaded_file_(File): File's clauses are loaded, in load order.
:- dynamic loaded_file_/1.
%   file_module_(File, Module): the module File's clauses went into.
:- dynamic file_module_/2.
%   module_role_(Module, Role): Role is case(Case), kind(Kind) or shared; in the order
%   the modules were first loaded.
:- dynamic module_role_/2.
%   module_scope_(Module, Scope): the modules Module's goals resolve in, itself first.
:- dynamic module_scope_/2.
%   primitive_(Name/Arity): a primitive fact predicate of some ontology module.
:- dynamic primitive_/1.
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
%   ontology(kinds/hook_like)) and assert its clauses into the module of its role (a
%   case's, a kind's, or the shared `kb`).  Calls in clause bodies are checked after the
%   load.
%
%   @error existence_error(source_sink, File) if File does not exist.
%   @error syntax_error(Message) with context file(Path, Line, LinePos, CharNo).
%   @error existence_error(procedure, Name/Arity) with context file(Path, Line, -1, 0)
%          for a call to an unknown predicate.
%   @error domain_error(ontology_clause, Term) for a directive (ontology files are data).
%   @error domain_error(one_role_per_file, Roles) with context file(Path, 1, -1, 0) for
%          a file declaring more than one case/1 or kind/1 fact.
%
%   ==
%   ?- load_ontology(ontology(ranges)), shared_holds(qualitative_value(handle_length, 0.3, V)).
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
    maplist(read_ontology_file_, Paths, Loads),
    check_tool_classes_(Loads),
    check_calls_(Loads),
    maplist(unload_file_, Paths),
    maplist(assert_file_, Loads),
    update_modules_.

%!  load_default_ontology is det.
%
%   Load every `.pl` file of the ontology directory (the `ontology` file search path
%   set by prolog/creative.pl, else ../ontology relative to this module) and of its
%   subdirectories (cases/, kinds/, ...), in a fixed order: a directory's files in name
%   order, then each subdirectory in name order, depth first.  The order is the order of
%   the clauses of a predicate that several files of one module define.
%
%   ==
%   ?- load_default_ontology, kb_kind_module(hook_like, M),
%      kb_module_holds(M, subclass_of(hook, C)).
%   M = kind_hook_like, C = hook_like.
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

%   read_ontology_file_(+Path, -Load): Load = load(Path, Module, Role, Items), Items
%   the file's item(Clause, Path, Line) terms.
read_ontology_file_(Path, load(Path, Module, Role, Items)) :-
    read_file_clauses_(Path, Items, []),
    file_role_(Path, Items, Role),
    role_module_(Role, Module).

%   file_role_(+Path, +Items, -Role): case(Case) for a file with one case/1 fact,
%   kind(Kind) for one with one kind/1 fact, apparatus(A) for one with one
%   apparatus/1 fact, shared otherwise.
file_role_(Path, Items, Role) :-
    findall(R,
            ( member(item(T, _, _), Items),
              ( T = case(C), R = case(C)
              ; T = kind(K), R = kind(K)
              ; T = apparatus(A), R = apparatus(A)
              ) ),
            Roles),
    (   Roles == []
    ->  Role = shared
    ;   Roles = [Role],
        Role =.. [_, Id],
        atom(Id)
    ->  true
    ;   throw(error(domain_error(one_role_per_file, Roles), file(Path, 1, -1, 0)))
    ).

role_module_(shared, kb).
role_module_(case(C), M) :-
    atom_concat(case_, C, M).
role_module_(kind(K), M) :-
    atom_concat(kind_, K, M).
role_module_(apparatus(A), M) :-
    atom_concat(apparatus_, A, M).

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

%   check_tool_classes_(+Loads): the class a case's case_tool_class/2 fact names is a
%   class of some kind (its file has a subclass_of(Class, _) fact), when any kind is
%   loaded at all; else
%   error(existence_error(tool_class, Class, root_classes(Roots)), file(Path, Line, -1, 0)),
%   Roots the Root-KindFile pairs of the kinds (printed as one line saying what to
%   rename).
check_tool_classes_(Loads) :-
    findall(Root-File, kind_root_(Loads, Root, File), Roots),
    (   Roots == []
    ->  true
    ;   forall(( member(load(Path, _, case(C), Items), Loads),
                 member(item(case_tool_class(C, K), Path, Line), Items),
                 atom(K),
                 \+ class_kind_module_(K, Loads, _) ),
               throw(error(existence_error(tool_class, K, root_classes(Roots)),
                           file(Path, Line, -1, 0))))
    ).

%   kind_root_(+Loads, -Root, -File): Root is the root class of the kind loaded from
%   File (a class of its hierarchy whose parent is no class of it: under tool or
%   object), among the files being loaded, then those loaded before.
kind_root_(Loads, Root, File) :-
    member(load(File, _, kind(_), Items), Loads),
    member(item(subclass_of(Root, Parent), _, _), Items),
    \+ memberchk(item(subclass_of(Parent, _), _, _), Items).
kind_root_(Loads, Root, File) :-
    module_role_(M, kind(_)),
    \+ member(load(_, M, _, _), Loads),
    file_module_(File, M),
    kb_module_defines(M, subclass_of/2),
    M:subclass_of(Root, Parent),
    \+ M:subclass_of(Parent, _).

:- multifile prolog:error_message//1.

prolog:error_message(existence_error(tool_class, Class, root_classes(Roots))) -->
    [ 'case_tool_class/2 names the tool class ~q, which no kind of ontology/kinds/ has: '-
      [Class],
      'rename it to a kind\'s root class ('
    ],
    root_classes_message_(Roots),
    [ '), or add subclass_of(~q, tool) to its kind\'s file'-[Class] ].

root_classes_message_([]) --> [].
root_classes_message_([Root-File|Rest]) -->
    { file_base_name(File, Base) },
    [ '~q of kinds/~w'-[Root, Base] ],
    (   { Rest == [] }
    ->  []
    ;   [ ', ' ],
        root_classes_message_(Rest)
    ).

%   check_calls_(+Loads): every called predicate is known where it is called: defined
%   by a module the file's module sees (new clauses of this load, or clauses loaded
%   before), a primitive, or built in.
check_calls_(Loads) :-
    findall(M-(N/A),
            ( member(load(_, M, _, Items), Loads),
              member(item(C, _, _), Items),
              clause_head_(C, H),
              functor(H, N, A) ),
            NewDefined),
    findall(PI,
            ( member(load(_, _, _, Items), Loads),
              member(item(primitive_predicate(PI), _, _), Items) ),
            NewPrimitive),
    forall(member(load(_, M, Role, Items), Loads),
           ( visible_modules_(Role, M, Loads, Visible),
             findall(PI, ( member(V-PI, NewDefined), memberchk(V, Visible) ), Defined0),
             append(Defined0, NewPrimitive, Defined1),
             sort(Defined1, Defined),
             forall(member(item(C, Path, Line), Items),
                    ( clause_body_(C, Body),
                      check_body_(Body, Visible, Defined, Path, Line) )) )).

%   visible_modules_(+Role, +Module, +Loads, -Visible): the modules whose predicates a
%   body in Module may call: a case's own, its kind's, its apparatus' and kb; a kind's
%   or an apparatus' own and kb; for kb (the shared files), every module.
visible_modules_(case(C), M, Loads, Visible) :-
    (   (   member(load(_, M, _, Items), Loads),
            member(item(case_tool_class(C, K), _, _), Items)
        ;   kb_module_defines(M, case_tool_class/2),
            M:case_tool_class(C, K)
        ),
        atom(K),
        class_kind_module_(K, Loads, KM0)
    ->  KM = KM0
    ;   KM = kb
    ),
    !,
    findall(AM,
            ( (   member(load(_, M, _, Items), Loads)
              ->  member(item(case_apparatus(C, A), _, _), Items)
              ;   kb_module_defines(M, case_apparatus/2),
                  M:case_apparatus(C, A)
              ),
              atom(A),
              role_module_(apparatus(A), AM) ),
            AMs),
    append([[M, KM], AMs, [kb]], Visible0),
    list_to_set(Visible0, Visible).
visible_modules_(kind(_), M, _, [M, kb]).
visible_modules_(apparatus(_), M, _, [M, kb]).

visible_modules_(shared, _, Loads, Visible) :-
    findall(M, module_role_(M, _), Old),
    findall(M, member(load(_, M, _, _), Loads), New),
    append([[kb], Old, New], Visible0),
    list_to_set(Visible0, Visible).

%   class_kind_module_(+Class, +Loads, -Module): the module of the kind whose hierarchy
%   holds the tool class Class (its file has a subclass_of(Class, _) fact; the kind's
%   own name, its kind/1 fact and its file's name, need not be the class's), among the
%   files being loaded, then those loaded before.
class_kind_module_(K, Loads, KM) :-
    (   member(load(_, KM, kind(_), Items), Loads),
        memberchk(item(subclass_of(K, _), _, _), Items)
    ->  true
    ;   module_role_(KM, kind(_)),
        \+ member(load(_, KM, _, _), Loads),
        kb_module_defines(KM, subclass_of/2),
        KM:subclass_of(K, _)
    ->  true
    ).

clause_head_((H :- _), H) :- !.
clause_head_(H, H).

clause_body_((_ :- B), B) :- !.
clause_body_(_, true).

check_body_(G, _, _, _, _) :-
    var(G),
    !.
check_body_(G, Visible, Defined, Path, Line) :-
    control_(G, Subgoals),
    !,
    forall(member(S, Subgoals), check_body_(S, Visible, Defined, Path, Line)).
check_body_(G, Visible, Defined, Path, Line) :-
    functor(G, N, A),
    (   known_predicate_(N/A, G, Visible, Defined)
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

known_predicate_(PI, _, _, Defined) :-
    memberchk(PI, Defined),
    !.
known_predicate_(PI, _, Visible, _) :-
    member(M, Visible),
    kb_module_defines(M, PI),
    !.
known_predicate_(PI, _, _, _) :-
    primitive_(PI),
    !.
known_predicate_(_, G, _, _) :-
    predicate_property(kb:G, defined).

unload_file_(Path) :-
    forall(retract(ontology_clause_(Path, Ref)), erase(Ref)),
    retractall(loaded_file_(Path)),
    retractall(file_module_(Path, _)).

%   assert_file_(+Load): a new module is set up (its default import kb) before its
%   first clause; update_modules_/0 adds its kind's module once every file is in.
assert_file_(load(Path, M, Role, Items)) :-
    (   module_role_(M, _)
    ->  true
    ;   M == kb
    ->  assertz(module_role_(kb, shared))
    ;   set_module(M:base(kb)),
        set_module(M:class(user)),
        assertz(module_role_(M, Role))
    ),
    forall(member(item(Clause, _, _), Items),
           ( assertz(M:Clause, Ref),
             assertz(ontology_clause_(Path, Ref)) )),
    assertz(loaded_file_(Path)),
    assertz(file_module_(Path, M)).

%   update_modules_: every case module imports its kind's module, scopes and the
%   primitive predicates are recomputed, and primitive fact predicates exist (dynamic,
%   in kb) before any world fact is asserted, so that asking about them fails instead
%   of raising.
update_modules_ :-
    retractall(module_scope_(_, _)),
    forall(module_role_(M, Role),
           ( module_scope_of_(Role, M, Scope),
             assertz(module_scope_(M, Scope)),
             reverse(Scope, Reversed),
             forall(( member(I, Reversed), I \== M, I \== kb ),
                    add_import_module(M, I, start)) )),
    retractall(primitive_(_)),
    forall(( module_role_(M, _),
             kb_module_defines(M, primitive_predicate/1),
             M:primitive_predicate(PI),
             \+ primitive_(PI) ),
           assertz(primitive_(PI))),
    forall(primitive_(N/A), dynamic(kb:N/A)).

module_scope_of_(shared, kb, [kb]).
module_scope_of_(kind(_), M, [M, kb]).
module_scope_of_(apparatus(_), M, [M, kb]).
module_scope_of_(case(C), M, Scope) :-
    (   kb_module_defines(M, case_tool_class/2),
        once(M:case_tool_class(C, K)),
        atom(K),
        class_kind_module_(K, [], KM)
    ->  KMs = [KM]
    ;   KMs = []
    ),
    findall(AM,
            ( kb_module_defines(M, case_apparatus/2),
              M:case_apparatus(C, A),
              atom(A),
              role_module_(apparatus(A), AM),
              module_role_(AM, apparatus(A)) ),
            AMs),
    append([[M], KMs, AMs, [kb]], Scope0),
    list_to_set(Scope0, Scope).

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

%!  kb_case_module(?Case, ?Module) is nondet.
%
%   Module holds the knowledge of the loaded case Case (its file's case/1 fact), in
%   load order.
%
%   ==
%   ?- load_default_ontology, kb_case_module(hook, M).
%   M = case_hook.
%   ==
kb_case_module(Case, Module) :-
    module_role_(Module, case(Case)).

%!  kb_kind_module(?Kind, ?Module) is nondet.
%
%   Module holds the knowledge of the loaded tool kind Kind (its file's kind/1 fact).
%
%   ==
%   ?- load_default_ontology, kb_kind_module(block, M).
%   M = kind_block.
%   ==
kb_kind_module(Kind, Module) :-
    module_role_(Module, kind(Kind)).

%!  kb_apparatus_module(?Apparatus, ?Module) is nondet.
%
%   Module holds the knowledge of the loaded apparatus Apparatus (its file's
%   apparatus/1 fact), which the cases naming it by case_apparatus/2 see.
%
%   ==
%   ?- load_default_ontology, kb_apparatus_module(tube, M).
%   M = apparatus_tube.
%   ==
kb_apparatus_module(Apparatus, Module) :-
    module_role_(Module, apparatus(Apparatus)).

%!  kb_modules(-Modules:list) is det.
%
%   Modules are the modules of the loaded ontology, in the order they were first
%   loaded (kb, the shared module, when a shared file is loaded).
kb_modules(Modules) :-
    findall(M, module_role_(M, _), Modules).

%!  kb_module_scope(+Module, -Scope:list) is det.
%
%   Scope lists the ontology modules a goal called in Module resolves in, Module first:
%   [case_hook, kind_hook_like, apparatus_tube, kb] for a case (its kind, its
%   apparatus), [kind_block, kb] for a kind or an apparatus, [kb].
kb_module_scope(Module, Scope) :-
    (   module_scope_(Module, Scope0)
    ->  Scope = Scope0
    ;   Scope = [kb]
    ).

%!  kb_module_defines(+Module, +Name/Arity) is semidet.
%
%   Module itself (not a module it imports from) has clauses or a dynamic declaration
%   for Name/Arity.
kb_module_defines(Module, N/A) :-
    current_predicate(Module:N/A),
    functor(H, N, A),
    \+ predicate_property(Module:H, imported_from(_)).

%!  kb_module_holds(+Module, +Goal) is nondet.
%
%   Call Goal in Module, if Module itself defines Goal's predicate; fail otherwise.
%   Its rules see what Module sees (kb_module_scope/2) and the world facts.
kb_module_holds(Module, Goal) :-
    must_be(callable, Goal),
    functor(Goal, N, A),
    kb_module_defines(Module, N/A),
    call(Module:Goal).

%!  kb_module_clause(+Module, ?Head, ?Body) is nondet.
%
%   Head :- Body is a clause of Module's own predicate (Body = true for a fact), in the
%   order the clauses were loaded.
kb_module_clause(Module, Head, Body) :-
    must_be(callable, Head),
    functor(Head, N, A),
    kb_module_defines(Module, N/A),
    clause(Module:Head, Body).

%!  shared_holds(:Goal) is nondet.
%
%   Call Goal in the shared knowledge (module kb: ranges, replacement operators, the
%   robot's skills, the world frame) and the asserted world facts.
%
%   ==
%   ?- load_default_ontology, kb_assert_facts([pose(cube1, 0.9, 0.0, 0.0, 0.0)]),
%      shared_holds(pose(cube1, X, _, _, _)).
%   X = 0.9.
%   ==
shared_holds(Goal) :-
    must_be(callable, Goal),
    call(kb:Goal).

%!  shared_clause(?Head, ?Body) is nondet.
%
%   Head :- Body is a clause of the shared knowledge (module kb), in the order the
%   clauses were loaded.
%
%   ==
%   ?- load_default_ontology, shared_clause(any_length(X), B).
%   B = handle_length(X, medium) ;
%   B = handle_length(X, long) ;
%   B = handle_length(X, short).
%   ==
shared_clause(Head, Body) :-
    kb_module_clause(kb, Head, Body).

%!  ontology_clause(?Head, ?Body) is nondet.
%
%   Head :- Body is a clause of the loaded ontology in any of its modules (kb, then the
%   case and kind modules in load order): what a kind brings of the shared vocabulary,
%   such as its replacement operators (ontology/kinds/paddle.pl), beside ontology/
%   replacement.pl's.
%
%   ==
%   ?- load_default_ontology, ontology_clause(replacement_operator(O), true).
%   O = any_length ; ...
%   ==
ontology_clause(Head, Body) :-
    kb_modules(Modules),
    member(M, Modules),
    kb_module_clause(M, Head, Body).

%!  shared_prove(+Goal, +Facts:list) is nondet.
%
%   kb_module_prove/3 in the shared module kb.
%
%   ==
%   ?- load_default_ontology, shared_prove(wrap_angle(4.0, A), []).
%   A = -2.2831853071795862.
%   ==
shared_prove(Goal, Facts) :-
    kb_module_prove(kb, Goal, Facts).

%!  kb_module_prove(+Module, +Goal, +Facts:list) is nondet.
%
%   Prove Goal in Module from the ontology's rules, taking primitive facts (those of
%   the ontology's primitive_predicate/1 declarations) from the list Facts instead of
%   the database.  Rules are interpreted clause by clause, each goal in the first
%   module of its clause's scope (kb_module_scope/2) that defines it, as SWI-Prolog
%   resolves it; built-in goals are called.
%
%   ==
%   ?- load_default_ontology,
%      kb_module_prove(case_hook, handle_length(h1, V),
%                      [object_kind(h1, hook), handle_length_m(h1, 0.5)]).
%   V = long.
%   ==
kb_module_prove(Module, Goal, Facts) :-
    must_be(atom, Module),
    must_be(callable, Goal),
    must_be(list, Facts),
    prove_(Goal, Module, Facts).

prove_(G, _, _) :-
    var(G),
    !,
    instantiation_error(G).
prove_(true, _, _) :- !.
prove_((A, B), M, Fs) :- !,
    prove_(A, M, Fs),
    prove_(B, M, Fs).
prove_((C -> T ; E), M, Fs) :- !,
    (   prove_(C, M, Fs)
    ->  prove_(T, M, Fs)
    ;   prove_(E, M, Fs)
    ).
prove_((C *-> T ; E), M, Fs) :- !,
    (   prove_(C, M, Fs)
    *-> prove_(T, M, Fs)
    ;   prove_(E, M, Fs)
    ).
prove_((A ; B), M, Fs) :- !,
    (   prove_(A, M, Fs)
    ;   prove_(B, M, Fs)
    ).
prove_((C -> T), M, Fs) :- !,
    (   prove_(C, M, Fs)
    ->  prove_(T, M, Fs)
    ).
prove_(\+ G, M, Fs) :- !,
    \+ prove_(G, M, Fs).
prove_(call(G), M, Fs) :- !,
    prove_(G, M, Fs).
prove_(once(G), M, Fs) :- !,
    once(prove_(G, M, Fs)).
prove_(findall(T, G, L), M, Fs) :- !,
    findall(T, prove_(G, M, Fs), L).
prove_(forall(C, A), M, Fs) :- !,
    forall(prove_(C, M, Fs), prove_(A, M, Fs)).
prove_(G, M, Fs) :-
    functor(G, N, A),
    (   primitive_(N/A)
    ->  member(G, Fs)
    ;   defining_module_(M, N/A, D)
    ->  clause(D:G, Body),
        prove_(Body, D, Fs)
    ;   call(M:G)
    ).

%   defining_module_(+Module, +PI, -Defining): the first module of Module's scope that
%   defines PI itself.
defining_module_(M, PI, D) :-
    kb_module_scope(M, Scope),
    member(D, Scope),
    kb_module_defines(D, PI),
    !.

%!  kb_assert_facts(+Facts:list) is det.
%
%   Add the ground facts Facts to the knowledge base as world facts (removed again by
%   kb_retract_facts/1, kb_reset/0).
%
%   @error instantiation_error or type_error(callable, F) for a fact that is not ground
%          and callable; type_error(fact, (H :- B)) for a clause with a body.
%
%   ==
%   ?- kb_assert_facts([pose(cube1, 0.9, 0.0, -0.05, 0.0)]), shared_holds(pose(cube1, X, _, _, _)).
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
%   learned_hypothesis(Task, Bound, Clause) (Bound is hs, hg, or prior: the literals of
%   h_g a prior gave, transfer.pl), as written in a run's
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
        must_be(oneof([hs, hg, prior]), Bound),
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
    retractall(file_module_(_, _)),
    findall(M, module_role_(M, _), Ms0),
    list_to_set([kb|Ms0], Ms),
    forall(( member(M, Ms),
             current_predicate(M:N/A),
             functor(H, N, A),
             \+ predicate_property(M:H, imported_from(_)),
             predicate_property(M:H, dynamic)
           ),
           abolish(M:N/A)),
    retractall(module_role_(_, _)),
    retractall(module_scope_(_, _)),
    retractall(primitive_(_)).
