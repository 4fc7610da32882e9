/*  Pushers: a head of upright walls hung below the end of a pole, for pushing or
    sweeping things along a table.  The hierarchy, the rules that turn the catalogue
    (metres) into qualitative structural literals, the size model of a new pusher and
    its replacement operators.

    Plain Prolog data loaded into its own module (kind_pusher, from kind/1 below) by
    knowledge:load_ontology/1.  A case whose tools are pushers says so with
    case_tool_class(Case, pusher).  Its Python side is creative_py/kinds/pusher.py (the
    spec, its parts and files, how the simulator holds it: by the pole, like a hook's
    handle, the head hanging below).

        tool
        └── pusher                    pole + head: pole_length, pole_width,
                                      plate_width, wing_length, wing_spread

    The head is a base plate across the pole's end (plate_width) and two wings running
    forward from its ends (wing_length), each tip standing out wing_spread beyond the
    plate (none: parallel wings or no wings; flared: a funnel).  The property names are
    the pusher's own, so that no property is shared with another hierarchy.
*/

kind(pusher).

subclass_of(pusher, tool).

class_part(pusher, pole).
class_part(pusher, head).

class_property(pusher, pole_length).
class_property(pusher, pole_width).
class_property(pusher, plate_width).
class_property(pusher, wing_length).
class_property(pusher, wing_spread).

%   qualitative_range(?Property, ?Value, ?Low, ?High, ?Bounds): metres.
qualitative_range(pole_length, short,  0.10, 0.30, closed_open).
qualitative_range(pole_length, medium, 0.30, 0.50, closed_open).
qualitative_range(pole_length, long,   0.50, 0.80, closed_closed).
qualitative_range(pole_width, thin,  0.006, 0.012, closed_open).
qualitative_range(pole_width, thick, 0.012, 0.030, closed_closed).
qualitative_range(plate_width, narrow, 0.03, 0.12, closed_open).
qualitative_range(plate_width, medium, 0.12, 0.30, closed_open).
qualitative_range(plate_width, wide,   0.30, 0.60, closed_closed).
qualitative_range(wing_length, none,  0.0, 0.01, closed_open).
qualitative_range(wing_length, short, 0.01, 0.10, closed_open).
qualitative_range(wing_length, long,  0.10, 0.30, closed_closed).
qualitative_range(wing_spread, none,    0.0, 0.01, closed_open).
qualitative_range(wing_spread, flared,  0.01, 0.30, closed_closed).

%   qualitative_value(+Property, +X, ?Value): the number X lies in Value's range above
%   (the pusher reads its own ranges: this file loads into its own module).
qualitative_value(Property, X, Value) :-
    qualitative_range(Property, Value, Low, High, Bounds),
    range_contains(Bounds, Low, High, X).

primitive_predicate(object_kind/2).
primitive_predicate(pole_length_m/2).
primitive_predicate(pole_width_m/2).
primitive_predicate(plate_width_m/2).
primitive_predicate(wing_length_m/2).
primitive_predicate(wing_spread_m/2).

catalogue_predicate(pusher, object_kind/2).
catalogue_predicate(pusher, pole_length_m/2).
catalogue_predicate(pusher, pole_width_m/2).
catalogue_predicate(pusher, plate_width_m/2).
catalogue_predicate(pusher, wing_length_m/2).
catalogue_predicate(pusher, wing_spread_m/2).

structural_predicate(pusher, tool/1).
structural_predicate(pusher, pusher/1).
structural_predicate(pusher, pole_length/2).
structural_predicate(pusher, pole_width/2).
structural_predicate(pusher, plate_width/2).
structural_predicate(pusher, wing_length/2).
structural_predicate(pusher, wing_spread/2).

tool(T) :-
    pusher(T).

pusher(T) :-
    object_kind(T, pusher).

pole_length(T, Value) :-
    pusher(T),
    pole_length_m(T, L),
    qualitative_value(pole_length, L, Value).

pole_width(T, Value) :-
    pusher(T),
    pole_width_m(T, W),
    qualitative_value(pole_width, W, Value).

plate_width(T, Value) :-
    pusher(T),
    plate_width_m(T, W),
    qualitative_value(plate_width, W, Value).

wing_length(T, Value) :-
    pusher(T),
    wing_length_m(T, L),
    qualitative_value(wing_length, L, Value).

wing_spread(T, Value) :-
    pusher(T),
    wing_spread_m(T, S),
    qualitative_value(wing_spread, S, Value).

%   new_tool_kind(?Class, +Structural, -Kind): a new pusher is sized as a pusher.
new_tool_kind(pusher, _, pusher).

%   Replacement operators (after the shared ones and the paddle's, in the order creation
%   tries properties): the wings' spread first (a funnel gathers what a straight head
%   leaves beside it), then the plate's width, then the pole's length.
replacement_operator(any_wing_spread).
replacement_operator(any_plate_width).
replacement_operator(any_pole_length).

any_wing_spread(X) :- wing_spread(X, none).
any_wing_spread(X) :- wing_spread(X, flared).

any_plate_width(X) :- plate_width(X, medium).
any_plate_width(X) :- plate_width(X, wide).
any_plate_width(X) :- plate_width(X, narrow).

any_pole_length(X) :- pole_length(X, medium).
any_pole_length(X) :- pole_length(X, long).
any_pole_length(X) :- pole_length(X, short).

                 /*******************************
                 *     SIZING A NEW PUSHER      *
                 *******************************/

%   Field names are those of PusherSpec in creative_py/kinds/pusher.py (metres).
size_field(pusher, pole_length, pole_length).
size_field(pusher, pole_width, pole_width).
size_field(pusher, plate_width, plate_width).
size_field(pusher, wing_length, wing_length).
size_field(pusher, wing_spread, wing_spread).

size_constraint(pusher, max_tool_length(M), [pole_length =< M]).
size_constraint(pusher, min_wall_m(M), [pole_width >= M]).

%   The strength check (creative_py/fabrication/strength.py): the pole is the handle
%   that bends, a cantilever from the grasp.
size_constraint(pusher, min_handle_width_m(W), [pole_width >= W]).
