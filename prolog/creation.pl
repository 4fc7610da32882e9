:- module(creation,
          [ creation_candidates/3,   % +VS, +Options, -Candidates
            catalogue_first/5,       % +Case, +VS, +Primitive, +Exclude, -Result
            next_tool/6              % +Case, +VS, +Tried, +Context, +Options, -Result
          ]).

/** <module> Tool creation by Marvin-style replacement (the paper's Algorithm 2)

Tool creation starts from the most specific hypothesis h_s of the learned tool-use model
(its structural literals describe the tool of the last positive example). One structural
literal is generalised with a replacement operator of the ontology
(replacement:replacement/3, e.g. handle_length(T, medium) -> any_length(T)) and the new
tool is an instance that does *not* satisfy the replaced literal
(handle_length(T, long)). Its structural literals are then sized by CLP(R)
(geometry_clp:solve_size/5) within the task's geometry.

Order of the candidates (creation_candidates/3):

  1. Properties whose literal is in h_g come first: the physics showed them necessary,
     so a different value of them is the change most likely to matter. Then the other
     structural literals of h_s.
  2. Among those, properties in the order the ontology lists its replacement operators
     (ontology/replacement.pl: sizes first, then side, angle, shape and kind).
  3. Within a property, alternatives that a stored negative example refuted (a negative
     example whose only violated literal of h_s is this property and which had that
     alternative value, e.g. the short-handled hook that failed during tool-use
     learning) come after the others, which keep the ontology's order. This is where we depart from
     the paper, which tried the short wedge before the long one: the failure already
     told us which way to go.

A new tool keeps only the properties of its class: when the replaced literal is a
class literal (hook(T) -> stick(T)), the structural literals of properties that neither
the new class nor its superclasses have (class_property/2: the prong's hook_length/2,
...) leave it.  The kind it is sized as comes from the case's tool class through these
hook predicates (case.pl says how a missing one is reported):

  - case_tool_class(?Case, ?Class): the hierarchy of the case's tools (hook_like,
    block).
  - new_tool_kind(?Class, +Structural, -Kind): the size kind (geometry_clp:solve_size/5)
    of a new tool with the structural literals Structural (hook_like: stick when
    stick(T) is among them, else hook).
*/

:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(error)).
:- use_module(library(option)).
:- use_module(version_space).
:- use_module(replacement).
:- use_module(geometry_clp).
:- use_module(experiment).
:- use_module(knowledge, [ontology_clause/2]).
:- use_module(subsumption, [clause_covers/2, clause_head_body/3]).
:- use_module(case).

%!  creation_candidates(+VS, +Options, -Candidates) is det.
%
%   Candidates is the ordered list of
%   candidate(Replaced, General, Instance, Structural): Replaced is the literal of h_s
%   that is generalised to General; Instance the alternative value tried; Structural
%   the new tool's structural literals (those of h_s with Replaced swapped for
%   Instance). Options: exclude(Literals) leaves out properties (default []).

creation_candidates(VS, Options, Candidates) :-
    option(exclude(Excluded), Options, []),
    vs_bounds(VS, HS, HG),
    hypothesis_parts(HS, Struct, _, _),
    hypothesis_parts(HG, HGStruct, _, _),
    vs_examples(VS, _, Negs),
    findall(Key-candidate(L, General, Alt, NewStruct),
            ( nth1(I, Struct, L),
              \+ ( member(X, Excluded), X =@= L ),
              replacement(L, General, Alts),
              operator_rank_(General, Rank),
              (   memberchk_variant_(L, HGStruct)
              ->  Nec = 0
              ;   Nec = 1
              ),
              nth1(J, Alts, Alt),
              (   refuted_(HS, L, Alt, Negs)
              ->  Ref = 1
              ;   Ref = 0
              ),
              Key = k(Nec, Rank, Ref, I, J),
              replace_eq_(Struct, L, Alt, NewStruct0),
              kind_literals_(Alt, NewStruct0, NewStruct)
            ),
            Keyed),
    keysort(Keyed, Sorted),
    pairs_values(Sorted, Candidates).

%   A new tool keeps only the properties of its class: when Alt is a class literal
%   (stick(T)), the literals of properties that only other classes have (the prong's)
%   leave the new tool's structural literals.
kind_literals_(Alt, Struct0, Struct) :-
    (   compound(Alt),
        compound_name_arity(Alt, Class, 1),
        ontology_holds(subclass_of(Class, _))
    ->  exclude(foreign_property_(Class), Struct0, Struct)
    ;   Struct = Struct0
    ).

%   L is P(T, V) with P a property of some class that is neither Class nor above it.
foreign_property_(Class, L) :-
    compound(L),
    compound_name_arity(L, P, 2),
    ontology_holds(class_property(Owner, P)),
    \+ is_a_(Class, Owner),
    !.

%   is_a_(+Class, +Super): Class is Super or below it.
is_a_(C, C) :- !.
is_a_(C, Super) :-
    ontology_holds(subclass_of(C, C1)),
    is_a_(C1, Super),
    !.

%   The position of a replacement operator in the ontology: properties are tried in
%   the order the ontology lists its operators.
operator_rank_(General, Rank) :-
    functor(General, Op, _),
    findall(O, ontology_clause(replacement_operator(O), true), Ops),
    (   nth1(Rank, Ops, Op)
    ->  true
    ;   Rank = 0
    ).

memberchk_variant_(X, [Y|Ys]) :-
    (   X =@= Y
    ->  true
    ;   memberchk_variant_(X, Ys)
    ).

replace_eq_([], _, _, []).
replace_eq_([X|Xs], L, Alt, [Y|Ys]) :-
    (   X == L
    ->  Y = Alt
    ;   Y = X
    ),
    replace_eq_(Xs, L, Alt, Ys).

%   The kind of tool solve_size/5 sizes, from the case's tool class.
size_kind_(Case, Struct, Kind) :-
    case_answer(case_tool_class(Case, Class)),
    (   class_answer(new_tool_kind(Class, Struct, Kind0))
    ->  Kind = Kind0
    ;   domain_error(new_tool_kind(Class), Struct)
    ).

%   A negative example refutes Alt if the only literal of h_s it violates is L and its
%   body contains Alt (for its own tool).
refuted_(HS, L, Alt, Negs) :-
    member(Neg, Negs),
    clause_violations(HS, Neg, Viol),
    Viol = [V],
    V == L,
    copy_term(HS-Alt, HS1-Alt1),
    HS1 = (H1 :- _),
    Neg = (NH :- NB),
    H1 = NH,
    conj_member_(Alt1, NB),
    !.

conj_member_(X, (A, B)) :- !,
    (   X =@= A
    ->  true
    ;   conj_member_(X, B)
    ).
conj_member_(X, A) :-
    X =@= A.

%!  catalogue_first(+Case, +VS, +Primitive, +Exclude, -Result) is det.
%
%   The catalogued objects to try before a tool is made. The first candidate of
%   creation_candidates/3 names the literal Replaced of h_s that creation would
%   generalise to General; the *generalised model* is h_g with Replaced taken out and
%   General put in (as created_models/5 builds the created model with an instance).
%   It admits an available object (Primitive: the harder task's facts) when h_g
%   without Replaced covers the object's example (its structural literals, h_s's
%   spatial and task literals, as plan_use/5 builds it) and the object has one of the
%   alternative values of the property (General holds of it, Replaced does not: an
%   object with the replaced value is the learned concept that just failed). Objects
%   named in Exclude (those TC trial 1 tried) are left out.
%
%   Result is catalogue(Replaced, General, Objects), Objects a list of
%   catalogued(Object, Value, Use) best first, in the planner's order: the
%   alternative values in the order creation tries them (the instance next_tool/6
%   would make first, and so the created model the planner would use, comes first),
%   then the object's name (planner:plan/5's tie-break among the objects a model
%   admits: `hook_a4` before `hook_b4`). Use is plan_use/5's
%   answer with option tool(Object): exploit(Object, Violated, Pose, Required), or
%   no_experiment(Reason) when no pose satisfies the spatial literals. Result is
%   none if no literal of h_s can be generalised.

catalogue_first(Case, VS, Primitive, Exclude, Result) :-
    must_be(list, Exclude),
    creation_candidates(VS, [], Candidates),
    (   Candidates = [candidate(L, General0, _, _)|_]
    ->  findall(L1-Alt, ( member(candidate(L1, _, Alt, _), Candidates), L1 =@= L ),
                Values),
        vs_bounds(VS, HS, HG),
        hypothesis_parts(HS, Struct, Spatial, Task),
        once(( member(Replaced, Struct), Replaced =@= L )),
        copy_term(L-General0, Replaced-General),
        clause_head_body(HG, Head, HGLits),
        exclude(==(Replaced), HGLits, HGLits1),
        observed_state(Case, Primitive, State),
        task_objects(Case, State, Objects),
        findall(k(VI, O)-O-Value,
                ( member(object(O, OStruct), Objects),
                  \+ memberchk(O, Exclude),
                  nth1(VI, Values, LV-AltV),
                  copy_term(LV-AltV, LO-Value),
                  arg(1, LO, O),
                  memberchk(Value, OStruct),
                  copy_term(Head-(Spatial-Task)-HGLits1, HeadC-(Req-TaskC)-HGLitsC),
                  HeadC =.. [_, O|_],
                  append([OStruct, Req, TaskC], Body),
                  clause_head_body(Example, HeadC, Body),
                  clause_head_body(HGC, HeadC, HGLitsC),
                  clause_covers(HGC, Example)
                ),
                Keyed),
        keysort(Keyed, Sorted),
        findall(catalogued(O, Value, Use),
                ( member(_-O-Value, Sorted),
                  plan_use(Case, VS, Primitive, [tool(O)], Use)
                ),
                Items),
        Result = catalogue(Replaced, General, Items)
    ;   Result = none
    ).

%!  next_tool(+Case, +VS, +Tried, +Context, +Options, -Result) is det.
%
%   The next tool to create. Tried lists the Instance literals created before (compared
%   as variants). Context holds the task's geometry facts for the constraint solver.
%   Result is create(Replaced, General, Instance, Structural, Dims) with Dims the sized
%   dimensions (Name=Value, HookSpec/BlockSpec field names), or
%   exhausted(Skipped), Skipped a list of Instance-Reason for the candidates that were
%   tried before or could not be sized.

next_tool(Case, VS, Tried, Context, Options, Result) :-
    must_be(list, Tried),
    creation_candidates(VS, Options, Candidates),
    next_tool_(Candidates, Case, Tried, Context, [], Result).

next_tool_([], _, _, _, Skipped0, exhausted(Skipped)) :-
    reverse(Skipped0, Skipped).
next_tool_([candidate(L, G, Alt, Struct)|Cs], Case, Tried, Context, Skipped0, Result) :-
    (   memberchk_variant_(Alt, Tried)
    ->  next_tool_(Cs, Case, Tried, Context, [Alt-tried|Skipped0], Result)
    ;   size_kind_(Case, Struct, Kind),
        solve_size(Case, Kind, Struct, Context, Sized),
        (   Sized = dims(Dims)
        ->  Result = create(L, G, Alt, Struct, Dims)
        ;   Sized = infeasible(Conflict),
            next_tool_(Cs, Case, Tried, Context, [Alt-infeasible(Conflict)|Skipped0], Result)
        )
    ).
