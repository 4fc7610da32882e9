/*  Qualitative ranges: the metres (or degrees, or ratios) behind each qualitative value.

    Plain Prolog data loaded into the shared module kb by knowledge:load_ontology/1.

    qualitative_range(?Property, ?Value, ?Low, ?High, ?Bounds)
        Property takes the qualitative Value for a number X in the interval Low..High.
        Bounds says which ends are included: closed_open [Low, High), closed_closed
        [Low, High], open_closed (Low, High].  Units: metres for lengths and widths,
        degrees for hook_angle, a plain ratio (length / height) for
        mechanical_advantage.  The values of one property are listed in increasing
        order, and together they cover the property's whole domain without overlap.
*/

% Hook-like tools (metres, hook_angle in degrees).
qualitative_range(handle_length, short,  0.10, 0.25, closed_open).
qualitative_range(handle_length, medium, 0.25, 0.45, closed_open).
qualitative_range(handle_length, long,   0.45, 0.70, closed_closed).

qualitative_range(handle_width, thin,  0.006, 0.012, closed_open).
qualitative_range(handle_width, thick, 0.012, 0.030, closed_closed).

qualitative_range(hook_length, short, 0.010, 0.025, closed_open).
qualitative_range(hook_length, long,  0.025, 0.050, closed_closed).

qualitative_range(hook_width, narrow, 0.004, 0.008, closed_open).
qualitative_range(hook_width, wide,   0.008, 0.020, closed_closed).

qualitative_range(hook_angle, acute,   30, 75, closed_open).
qualitative_range(hook_angle, right,   75, 105, closed_closed).
qualitative_range(hook_angle, obtuse, 105, 150, open_closed).

% Blocks of the wedge case (metres; mechanical_advantage is length / height).
qualitative_range(block_length, short,  0.03, 0.07, closed_open).
qualitative_range(block_length, medium, 0.07, 0.12, closed_open).
qualitative_range(block_length, long,   0.12, 0.20, closed_closed).

qualitative_range(block_width, narrow, 0.02, 0.06, closed_open).
qualitative_range(block_width, wide,   0.06, 0.15, closed_closed).

qualitative_range(block_height, low,  0.015, 0.04, closed_open).
qualitative_range(block_height, high, 0.04,  0.08, closed_closed).

%   The ratio's domain follows from the block ranges: 0.03/0.08 = 0.375 up to
%   0.20/0.015 = 13.3.
%   A wedge's tip: the height of the flat at its thin end (ontology/kinds/block.pl).  A
%   sharp tip is thinner than two 0.4 mm nozzle widths and cannot be printed; a blunt
%   one can.  No structural literal names it: it is a dimension of the block size model
%   only (the catalogue's wedges are sharp, tool-use learning never sees it).
qualitative_range(tip_height, sharp, 0.0,    0.0008, closed_open).
qualitative_range(tip_height, blunt, 0.0008, 0.004,  closed_closed).

qualitative_range(mechanical_advantage, below_one, 0.375, 1.0, closed_closed).
qualitative_range(mechanical_advantage, above_one, 1.0, 13.5, open_closed).

%   qualitative_range(?Property, ?Value, ?Low, ?High): the interval without its bounds.
qualitative_range(Property, Value, Low, High) :-
    qualitative_range(Property, Value, Low, High, _).

%   qualitative_value(+Property, +X, ?Value): the number X lies in Value's interval.
qualitative_value(Property, X, Value) :-
    qualitative_range(Property, Value, Low, High, Bounds),
    range_contains(Bounds, Low, High, X).

range_contains(closed_open, Low, High, X) :-
    X >= Low,
    X < High.
range_contains(closed_closed, Low, High, X) :-
    X >= Low,
    X =< High.
range_contains(open_closed, Low, High, X) :-
    X > Low,
    X =< High.
