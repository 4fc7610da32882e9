:- begin_tests(engine_vocabulary).

:- use_module(library(lists)).
:- use_module(library(apply)).

/*  The engine names no case: no clause of a file of prolog/ mentions a case id, a role or
    extra object of a case, a pose term, a tool kind or a non-root tool class of the
    loaded ontology, or an apparatus several cases share (comments are not clauses, so
    PlDoc examples may).  Root classes
    (tool, object) are left out: `tool` is also the engine's parameter type.
*/

case_vocabulary_(Atoms) :-
    findall(A, case_atom_(A), As),
    sort(As, Atoms).

case_atom_(Case) :-
    ontology_holds(case(Case)).
case_atom_(Object) :-
    ontology_holds(task_roles(_, Target, Context)),
    member(Object, [Target, Context]).
case_atom_(Object) :-
    ontology_holds(case_extra_objects(_, Extra)),
    member(Object-_, Extra).
case_atom_(PoseName) :-
    ontology_holds(pose_domain(_, Pose, _)),
    functor(Pose, PoseName, _).
case_atom_(Class) :-
    ontology_holds(subclass_of(Class, _)).
case_atom_(Kind) :-
    ontology_holds(size_field(Kind, _, _)).
case_atom_(Apparatus) :-
    ontology_holds(apparatus(Apparatus)).

engine_file_(Path) :-
    module_property(knowledge, file(Here)),
    file_directory_name(Here, Dir),
    directory_files(Dir, Entries),
    member(E, Entries),
    file_name_extension(_, pl, E),
    directory_file_path(Dir, E, Path).

%   file_atoms_(+Path, -Atoms): every atom of every clause of Path, read with the
%   operators of the file's module.
file_atoms_(Path, Atoms) :-
    setup_call_cleanup(
        open(Path, read, In),
        ( read_term(In, First, []),
          (   First = (:- module(M, _))
          ->  true
          ;   M = user
          ),
          read_atoms_(In, M, [First], Terms)
        ),
        close(In)),
    findall(A, ( member(T, Terms), sub_term(A, T), atom(A) ), As),
    sort(As, Atoms).

read_atoms_(In, M, Acc, Terms) :-
    read_term(In, T, [module(M)]),
    (   T == end_of_file
    ->  Terms = Acc
    ;   read_atoms_(In, M, [T|Acc], Terms)
    ).

test(vocabulary_is_known) :-
    case_vocabulary_(V),
    assertion(subset([hook, wedge, cube1, tube1, door1, floor1, hook_pose, wedge_pose,
                      stick, block, hook_like, tube], V)).

test(engine_names_no_case, Found == []) :-
    case_vocabulary_(V),
    findall(Base-A,
            ( engine_file_(Path),
              file_atoms_(Path, Atoms),
              member(A, Atoms),
              memberchk(A, V),
              file_base_name(Path, Base)
            ),
            Found).

:- end_tests(engine_vocabulary).
