:- begin_tests(replacement, [setup(load_default_ontology)]).

:- use_module('../../prolog/knowledge').
:- use_module('../../prolog/replacement').

test(paper_handle_length_example) :-
    replacement(handle_length(T, medium), G, As),
    assertion(G =@= any_length(T)),
    assertion(As =@= [handle_length(T, long), handle_length(T, short)]).

test(ground_object) :-
    replacement(handle_length(hook_a2, short), G, As),
    assertion(G == any_length(hook_a2)),
    assertion(As == [handle_length(hook_a2, medium), handle_length(hook_a2, long)]).

test(paper_wedge_example_short_first) :-
    replacement(block_length(w, medium), G, As),
    assertion(G == any_block_length(w)),
    assertion(As == [block_length(w, short), block_length(w, long)]).

test(hook_side_either_side) :-
    replacement(hook_side(t, right), G, As),
    assertion(G == any_side(t)),
    assertion(As == [hook_side(t, left)]).

test(shape) :-
    replacement(shape(w, box), any_shape(w), As),
    assertion(As == [shape(w, triangular_prism), shape(w, cylinder)]).

test(alternatives_do_not_satisfy_replaced_literal) :-
    forall(( shared_clause(replacement_operator(Op), true),
             H =.. [Op, x],
             shared_clause(H, L) ),
           ( replacement(L, G, As),
             assertion(G == H),
             assertion(\+ memberchk(L, As)) )).

test(no_operator_for_spatial_literal, [fail]) :-
    replacement(behind(h, cube1), _, _).

test(value_must_be_known, [fail]) :-
    replacement(handle_length(_, _), _, _).

:- end_tests(replacement).
