/*  Marvin-style replacement operators (paper, Section 4.1): each operator generalises
    one structural property; its clauses list the property's values.

    Plain Prolog data loaded into the shared module kb by knowledge:load_ontology/1.
    replacement:replacement/3 reads these clauses in the order written here, so the
    order is the order in which alternative values are tried: any_length/1 is the
    paper's own (medium, long, short: a medium handle is replaced by a long one first,
    as in the paper's longer-tube experiment), any_block_length/1 follows the paper's
    wedge experiment (a medium wedge is replaced by a short one first, then a long one).
*/

%   The order of the operators is the order in which tool creation
%   (prolog/creation.pl) tries properties: sizes first, because a task that grows (a
%   longer tube, a stronger door closer) changes which sizes suffice, then side, angle,
%   shape and kind.
replacement_operator(any_length).
replacement_operator(any_hook_length).
replacement_operator(any_width).
replacement_operator(any_hook_width).
replacement_operator(any_block_length).
replacement_operator(any_block_height).
replacement_operator(any_block_width).
replacement_operator(any_advantage).
replacement_operator(any_side).
replacement_operator(any_angle).
replacement_operator(any_shape).
replacement_operator(any_kind).

any_kind(X) :- hook(X).
any_kind(X) :- stick(X).

any_length(X) :- handle_length(X, medium).
any_length(X) :- handle_length(X, long).
any_length(X) :- handle_length(X, short).

any_width(X) :- handle_width(X, thin).
any_width(X) :- handle_width(X, thick).

any_hook_length(X) :- hook_length(X, short).
any_hook_length(X) :- hook_length(X, long).

any_hook_width(X) :- hook_width(X, narrow).
any_hook_width(X) :- hook_width(X, wide).

any_side(X) :- hook_side(X, right).
any_side(X) :- hook_side(X, left).

any_angle(X) :- hook_angle(X, right).
any_angle(X) :- hook_angle(X, acute).
any_angle(X) :- hook_angle(X, obtuse).

any_shape(X) :- shape(X, triangular_prism).
any_shape(X) :- shape(X, box).
any_shape(X) :- shape(X, cylinder).

any_block_length(X) :- block_length(X, medium).
any_block_length(X) :- block_length(X, short).
any_block_length(X) :- block_length(X, long).

any_block_width(X) :- block_width(X, narrow).
any_block_width(X) :- block_width(X, wide).

any_block_height(X) :- block_height(X, low).
any_block_height(X) :- block_height(X, high).

any_advantage(X) :- mechanical_advantage(X, above_one).
any_advantage(X) :- mechanical_advantage(X, below_one).
