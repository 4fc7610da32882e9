/*  Hook-like tools: the hierarchy of the paper's Figure 1 and the rules that turn the
    catalogue (numbers in metres and degrees) into qualitative structural literals.

    Plain Prolog data loaded into the knowledge base by knowledge:load_ontology/1.

        tool
        └── hook_like                 has a handle: handle_length, handle_width
            ├── hook                  handle + prong: hook_length, hook_width,
            │                         hook_side, hook_angle
            └── stick                 handle only
*/

% The hierarchy: subclass_of(?Class, ?Superclass).
subclass_of(hook_like, tool).
subclass_of(hook, hook_like).
subclass_of(stick, hook_like).

% The parts each class adds: class_part(?Class, ?Part).
class_part(hook_like, handle).
class_part(hook, prong).

% The structural properties each class adds, in the order the replacement operators
% are tried: class_property(?Class, ?Property).
class_property(hook_like, handle_length).
class_property(hook_like, handle_width).
class_property(hook, hook_length).
class_property(hook, hook_width).
class_property(hook, hook_side).
class_property(hook, hook_angle).

% Catalogue facts the world supplies for every hook-case object (metres, degrees).
primitive_predicate(object_kind/2).
primitive_predicate(handle_length_m/2).
primitive_predicate(handle_width_m/2).
primitive_predicate(hook_length_m/2).
primitive_predicate(hook_width_m/2).
primitive_predicate(hook_side_is/2).
primitive_predicate(hook_angle_deg/2).

% The structural literals abstract states carry for the hook case, in this order.
structural_predicate(hook, tool/1).
structural_predicate(hook, hook_like/1).
structural_predicate(hook, hook/1).
structural_predicate(hook, stick/1).
structural_predicate(hook, handle_length/2).
structural_predicate(hook, handle_width/2).
structural_predicate(hook, hook_length/2).
structural_predicate(hook, hook_width/2).
structural_predicate(hook, hook_side/2).
structural_predicate(hook, hook_angle/2).

% Class membership from the catalogue's kind.
tool(T) :-
    hook_like(T).

hook_like(T) :-
    object_kind(T, Kind),
    subclass_of(Kind, hook_like).

hook(T) :-
    object_kind(T, hook).

stick(T) :-
    object_kind(T, stick).

% Structural properties: catalogue numbers mapped through the qualitative ranges.
handle_length(T, Value) :-
    hook_like(T),
    handle_length_m(T, L),
    qualitative_value(handle_length, L, Value).

handle_width(T, Value) :-
    hook_like(T),
    handle_width_m(T, W),
    qualitative_value(handle_width, W, Value).

hook_length(T, Value) :-
    hook(T),
    hook_length_m(T, L),
    qualitative_value(hook_length, L, Value).

hook_width(T, Value) :-
    hook(T),
    hook_width_m(T, W),
    qualitative_value(hook_width, W, Value).

hook_side(T, Side) :-
    hook(T),
    hook_side_is(T, Side),
    side_value(Side).

hook_angle(T, Value) :-
    hook(T),
    hook_angle_deg(T, A),
    qualitative_value(hook_angle, A, Value).

side_value(left).
side_value(right).
