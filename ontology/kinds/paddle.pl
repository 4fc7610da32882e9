/*  Paddles: a flat blade at the end of a shaft, for pushing.  The hierarchy, the rules
    that turn the catalogue (metres) into qualitative structural literals, the size
    model of a new paddle and its replacement operators.

    Plain Prolog data loaded into its own module (kind_paddle, from kind/1 below) by
    knowledge:load_ontology/1.  A
    case whose tools are paddles says so with case_tool_class(Case, paddle).  Its
    Python side is creative_py/kinds/paddle.py (the spec, its parts and files, how the
    simulator holds it: by the shaft, like a hook's handle).

        tool
        └── paddle                    shaft + blade: shaft_length, shaft_width,
                                      blade_width, blade_length

    The blade is as thick as the shaft (shaft_width) and lies across it at its far
    end: blade_width across the shaft, blade_length along it.  The property names are
    the paddle's own, so that no property is shared with another hierarchy.
*/

kind(paddle).

subclass_of(paddle, tool).

class_part(paddle, shaft).
class_part(paddle, blade).

class_property(paddle, shaft_length).
class_property(paddle, shaft_width).
class_property(paddle, blade_width).
class_property(paddle, blade_length).

%   qualitative_range(?Property, ?Value, ?Low, ?High, ?Bounds): metres.
qualitative_range(shaft_length, short,  0.10, 0.25, closed_open).
qualitative_range(shaft_length, medium, 0.25, 0.45, closed_open).
qualitative_range(shaft_length, long,   0.45, 0.70, closed_closed).
qualitative_range(shaft_width, thin,  0.006, 0.012, closed_open).
qualitative_range(shaft_width, thick, 0.012, 0.030, closed_closed).
qualitative_range(blade_width, narrow, 0.030, 0.060, closed_open).
qualitative_range(blade_width, wide,   0.060, 0.120, closed_closed).
qualitative_range(blade_length, short, 0.010, 0.030, closed_open).
qualitative_range(blade_length, long,  0.030, 0.060, closed_closed).

%   qualitative_value(+Property, +X, ?Value): the number X lies in Value's range above.
%   The paddle reads its own ranges: ranges.pl's qualitative_value/3 sees only the
%   shared ones (this file loads into its own module, kind_paddle).
qualitative_value(Property, X, Value) :-
    qualitative_range(Property, Value, Low, High, Bounds),
    range_contains(Bounds, Low, High, X).

primitive_predicate(object_kind/2).
primitive_predicate(shaft_length_m/2).
primitive_predicate(shaft_width_m/2).
primitive_predicate(blade_width_m/2).
primitive_predicate(blade_length_m/2).

catalogue_predicate(paddle, object_kind/2).
catalogue_predicate(paddle, shaft_length_m/2).
catalogue_predicate(paddle, shaft_width_m/2).
catalogue_predicate(paddle, blade_width_m/2).
catalogue_predicate(paddle, blade_length_m/2).

structural_predicate(paddle, tool/1).
structural_predicate(paddle, paddle/1).
structural_predicate(paddle, shaft_length/2).
structural_predicate(paddle, shaft_width/2).
structural_predicate(paddle, blade_width/2).
structural_predicate(paddle, blade_length/2).

tool(T) :-
    paddle(T).

paddle(T) :-
    object_kind(T, paddle).

shaft_length(T, Value) :-
    paddle(T),
    shaft_length_m(T, L),
    qualitative_value(shaft_length, L, Value).

shaft_width(T, Value) :-
    paddle(T),
    shaft_width_m(T, W),
    qualitative_value(shaft_width, W, Value).

blade_width(T, Value) :-
    paddle(T),
    blade_width_m(T, W),
    qualitative_value(blade_width, W, Value).

blade_length(T, Value) :-
    paddle(T),
    blade_length_m(T, L),
    qualitative_value(blade_length, L, Value).

%   new_tool_kind(?Class, +Structural, -Kind): a new paddle is sized as a paddle.
new_tool_kind(paddle, _, paddle).

%   Replacement operators (ontology/replacement.pl has the others; these come after
%   them in the order creation tries properties).
replacement_operator(any_shaft_length).
replacement_operator(any_blade_width).

any_shaft_length(X) :- shaft_length(X, medium).
any_shaft_length(X) :- shaft_length(X, long).
any_shaft_length(X) :- shaft_length(X, short).

any_blade_width(X) :- blade_width(X, narrow).
any_blade_width(X) :- blade_width(X, wide).

                 /*******************************
                 *     SIZING A NEW PADDLE      *
                 *******************************/

%   Field names are those of PaddleSpec in creative_py/kinds/paddle.py (metres).
size_field(paddle, shaft_length, shaft_length).
size_field(paddle, shaft_width, shaft_width).
size_field(paddle, blade_width, blade_width).
size_field(paddle, blade_length, blade_length).

size_constraint(paddle, max_tool_length(M), [shaft_length =< M]).
size_constraint(paddle, min_wall_m(M), [shaft_width >= M, blade_length >= M]).

%   The strength check (creative_py/fabrication/strength.py): the shaft is the handle
%   that bends, a cantilever from the grasp.
size_constraint(paddle, min_handle_width_m(W), [shaft_width >= W]).
