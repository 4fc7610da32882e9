:- module(text_terms,
          [ text_terms/2,            % +Text, -Terms
            text_term/3,             % +Text, -Term, -Bindings
            term_depth_max/1,        % -Depth
            must_be_shallow/1        % +Term
          ]).

/** <module> Prolog text from outside read as data, never deeper than the C stack allows

A prior's model.pl and a command line's --context are text from outside the engine.
SWI-Prolog's reader and writer recurse on the C stack for each level of nesting, and
embedded with --nosignals (as pyswip starts it) a C-stack overflow is a SIGSEGV that
kills the process without a word (a term nested 100,000 deep did). So text from
outside is read here only: the Python side first refuses text whose brackets nest
too deep (creative_py/bridge/text.py: the reader's own recursion), and every term read is then checked with must_be_shallow/1 (operators nest without
brackets: `- - - a`, `a-b-c`), before anything writes or walks it in C.
The text's brackets may nest deeper (creative_py/bridge/text.py, BRACKETS_MAX):
they need not make terms (`((a))`, a chain f(a, f(b, ...)) written canonically). The terms are
only read, never called: a directive in the text is a term like any other.

    ?- text_terms("a(1). b :- c.", Ts).
    Ts = [a(1), (b:-c)].
*/

:- use_module(library(error)).

%!  term_depth_max(-Depth:integer) is det.
%
%   The deepest nesting of a term read from outside (creative_py/bridge/text.py's
%   DEPTH_MAX is the same number).

term_depth_max(200).

%!  text_terms(+Text, -Terms:list) is det.
%
%   Terms are the clauses of Text (a string or atom, each clause ending in a full
%   stop), in order, each checked with must_be_shallow/1. A syntax error raises the
%   reader's error(syntax_error(What), stream(_, Line, LinePos, CharNo)).

text_terms(Text, Terms) :-
    must_be(text, Text),
    setup_call_cleanup(open_string(Text, In),
                       read_terms_(In, Terms),
                       close(In)).

read_terms_(In, Terms) :-
    read_term(In, T, []),
    (   T == end_of_file
    ->  Terms = []
    ;   must_be_shallow(T),
        Terms = [T|Ts],
        read_terms_(In, Ts)
    ).

%!  text_term(+Text, -Term, -Bindings:list) is det.
%
%   Term is the one term of Text (no full stop), Bindings its Name=Var pairs,
%   checked with must_be_shallow/1. Text after the term (term_string/3 ignores
%   anything after a full stop: "a. b" would read as a) raises
%   syntax_error(one_term_expected).

text_term(Text, Term, Bindings) :-
    must_be(text, Text),
    string_concat(Text, "\n.", Clause),      % the newline ends a % comment
    setup_call_cleanup(open_string(Clause, In),
                       ( read_term(In, Term, [variable_names(Bindings)]),
                         read_term(In, Rest, []) ),
                       close(In)),
    (   Rest == end_of_file,
        Term \== end_of_file
    ->  must_be_shallow(Term)
    ;   syntax_error(one_term_expected)
    ).

%!  must_be_shallow(@Term) is det.
%
%   Raise error(representation_error(term_depth(Max)), _) when Term nests compounds
%   deeper than term_depth_max/1. A list's tail and the right-hand continuation of a
%   chain of one binary functor (a clause body a, b, c) do not count as nesting: the
%   writer and the bridge's codec walk those in a loop. Cyclic terms are refused
%   too (type_error(acyclic_term, _)); the error never holds Term.

must_be_shallow(Term) :-
    term_depth_max(Max),
    (   acyclic_term(Term)
    ->  true
    ;   type_error(acyclic_term, cyclic)
    ),
    (   shallow_(Term, Max)
    ->  true
    ;   throw(error(representation_error(term_depth(Max)), _))
    ).

shallow_(T, Left) :-
    (   compound(T)
    ->  Left > 0,
        Left1 is Left - 1,
        compound_name_arity(T, Name, Arity),
        (   Arity =:= 2
        ->  arg(1, T, A),
            shallow_(A, Left1),
            arg(2, T, B),
            chain_(B, Name, Left, Left1)
        ;   shallow_args_(1, Arity, T, Left1)
        )
    ;   true
    ).

% The right-hand side of F(A, B): another F/2 link keeps the level, anything else is
% one level down.
chain_(B, Name, Left, Left1) :-
    (   compound(B),
        compound_name_arity(B, Name, 2)
    ->  shallow_(B, Left)
    ;   shallow_(B, Left1)
    ).

shallow_args_(I, Arity, T, Left) :-
    (   I > Arity
    ->  true
    ;   arg(I, T, A),
        shallow_(A, Left),
        I1 is I + 1,
        shallow_args_(I1, Arity, T, Left)
    ).
