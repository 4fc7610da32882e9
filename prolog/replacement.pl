:- module(replacement,
          [ replacement/3             % +Literal, -General, -Alternatives
          ]).

/** <module> Marvin-style replacement: generalise a literal, list the other values

The ontology's replacement operators (ontology/replacement.pl) are predicates such as

    any_length(X) :- handle_length(X, medium).
    any_length(X) :- handle_length(X, long).
    any_length(X) :- handle_length(X, short).

declared by replacement_operator(any_length).  A literal that is the body of one of an
operator's clauses is *replaced* by the operator's head; the bodies of the other
clauses are the alternative instances, which do not satisfy the replaced literal
(paper, Section 4.1 and Algorithm 2, step 1).
*/

:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(knowledge, [ontology_clause/2]).

%!  replacement(+Literal, -General, -Alternatives:list) is semidet.
%
%   General is the generalisation of the structural Literal by the first replacement
%   operator (in ontology order) that has Literal as a clause body, applied to
%   Literal's object (its first argument); Alternatives are the operator's other clause
%   bodies for the same object, in the order the ontology lists the clauses (the
%   caller may reorder them).  Fails if no operator covers Literal.
%
%   ==
%   ?- replacement(handle_length(T, medium), G, As).
%   G = any_length(T),
%   As = [handle_length(T, long), handle_length(T, short)].
%   ?- replacement(behind(h, cube1), G, As).
%   false.
%   ==
replacement(Literal, General, Alternatives) :-
    must_be(callable, Literal),
    compound(Literal),
    arg(1, Literal, Object),
    once(( ontology_clause(replacement_operator(Op), true),
           operator_bodies_(Op, Object, Bodies),
           select(B, Bodies, Others),
           B =@= Literal
         )),
    General =.. [Op, Object],
    exclude(=@=(Literal), Others, Alternatives).

%   operator_bodies_(+Op, ?Object, -Bodies): the clause bodies of Op(Object), in order.
operator_bodies_(Op, Object, Bodies) :-
    Head =.. [Op, X],
    findall(X-Body, ontology_clause(Head, Body), Pairs),
    maplist(body_for_(Object), Pairs, Bodies).

body_for_(Object, X-Body, Body) :-
    X = Object.
