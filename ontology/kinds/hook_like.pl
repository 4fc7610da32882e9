/*  Hook-like tools: the hierarchy of the paper's Figure 1, the rules that turn the
    catalogue (numbers in metres and degrees) into qualitative structural literals, and
    the size models of a new hook or stick.

    Plain Prolog data loaded by knowledge:load_ontology/1 into its own module
    (kind_hook_like, named by the kind/1 fact below).  A case
    whose tools are hook-like says so with case_tool_class(Case, hook_like) and
    gets everything below.

        tool
        └── hook_like                 has a handle: handle_length, handle_width
            ├── hook                  handle + prong: hook_length, hook_width,
            │                         hook_side, hook_angle
            └── stick                 handle only
*/

%   This file is the kind hook_like: its clauses load into their own module (kind_hook_like),
%   seen by the cases whose case_tool_class/2 names it.
kind(hook_like).

% The hierarchy: subclass_of(?Class, ?Superclass).  A class without a superclass
% (tool) is a hierarchy's root: tool(O) marks O as a catalogued object.
subclass_of(hook_like, tool).
subclass_of(hook, hook_like).
subclass_of(stick, hook_like).

% The parts each class adds: class_part(?Class, ?Part).
class_part(hook_like, handle).
class_part(hook, prong).

% The structural properties each class adds, in the order the replacement operators
% are tried: class_property(?Class, ?Property).  A new tool of a class keeps only the
% properties of its class and its superclasses (a stick drops the prong's).
class_property(hook_like, handle_length).
class_property(hook_like, handle_width).
class_property(hook, hook_length).
class_property(hook, hook_width).
class_property(hook, hook_side).
class_property(hook, hook_angle).

% Catalogue facts the world supplies for every hook-like object (metres, degrees).
primitive_predicate(object_kind/2).
primitive_predicate(handle_length_m/2).
primitive_predicate(handle_width_m/2).
primitive_predicate(hook_length_m/2).
primitive_predicate(hook_width_m/2).
primitive_predicate(hook_side_is/2).
primitive_predicate(hook_angle_deg/2).

%   catalogue_predicate(?Class, ?Name/Arity): the catalogue's numeric facts about a tool
%   of the hierarchy (first argument: the tool).
catalogue_predicate(hook_like, object_kind/2).
catalogue_predicate(hook_like, handle_length_m/2).
catalogue_predicate(hook_like, handle_width_m/2).
catalogue_predicate(hook_like, hook_length_m/2).
catalogue_predicate(hook_like, hook_width_m/2).
catalogue_predicate(hook_like, hook_side_is/2).
catalogue_predicate(hook_like, hook_angle_deg/2).

%   structural_predicate(?Class, ?Name/Arity): the structural literals abstract states
%   carry for a tool of the hierarchy, in this order.  The unary ones are the class
%   literals.
structural_predicate(hook_like, tool/1).
structural_predicate(hook_like, hook_like/1).
structural_predicate(hook_like, hook/1).
structural_predicate(hook_like, stick/1).
structural_predicate(hook_like, handle_length/2).
structural_predicate(hook_like, handle_width/2).
structural_predicate(hook_like, hook_length/2).
structural_predicate(hook_like, hook_width/2).
structural_predicate(hook_like, hook_side/2).
structural_predicate(hook_like, hook_angle/2).

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

%   prong_half_m(+Tool, -Half), proved on the state: half the prong's thickness along
%   the handle, from the catalogue's hook_width_m/2, or, for a tool that has no such
%   fact, its handle_width_m/2: the prong_half geometry parameter of the hook-like
%   cases.
prong_half_m(Tool, Half) :-
    (   hook_width_m(Tool, W)
    ->  true
    ;   handle_width_m(Tool, W)
    ),
    Half is W / 2.

%   new_tool_kind(?Class, +Structural, -Kind): a new tool with the structural literals
%   Structural is sized (geometry_clp:solve_size/5) as a Kind: a stick when they say
%   so, else a hook.
new_tool_kind(hook_like, Structural, Kind) :-
    (   memberchk(stick(_), Structural)
    ->  Kind = stick
    ;   Kind = hook
    ).

                 /*******************************
                 *     SIZING A NEW TOOL        *
                 *******************************/

%   size_field(?Kind, ?Field, ?Property): the spec field Field of a new tool of kind
%   Kind is the number behind the qualitative Property (qualitative_range/5), in this
%   order.  Field names are those of HookSpec in creative_py/mesh/spec.py (metres,
%   hook_angle_deg in degrees).
size_field(hook, handle_length, handle_length).
size_field(hook, handle_width, handle_width).
size_field(hook, hook_length, hook_length).
size_field(hook, hook_width, hook_width).
size_field(hook, hook_angle_deg, hook_angle).
size_field(stick, handle_length, handle_length).
size_field(stick, handle_width, handle_width).

%   size_integer_field(?Field): a field in whole units (CLP(FD)), here degrees.
size_integer_field(hook_angle_deg).

%   size_choice(?Kind, ?Field, ?Property, ?Values): a field with symbolic values, the
%   values tried in this order when no literal fixes it.
size_choice(hook, hook_side, hook_side, [right, left]).

%   size_fixed(?Kind, ?Field, ?Value): a field a kind does not size (a stick has no
%   prong), in this order after the others.
size_fixed(stick, hook_length, 0.0).
size_fixed(stick, hook_width, 0.0).
size_fixed(stick, hook_side, none).
size_fixed(stick, hook_angle_deg, 90).

%   size_constraint(?Kind, ?ContextFact, ?Constraints): when the sizing context holds
%   ContextFact, a new tool of Kind satisfies the linear Constraints (field names,
%   size_parameter/3 names and the fact's numbers; see geometry_clp:size_constraints/4).
%   The manufacturing limits are the same in every case.
size_constraint(hook, max_tool_length(M), [handle_length =< M]).
size_constraint(stick, max_tool_length(M), [handle_length =< M]).
size_constraint(hook, min_wall_m(M), [handle_width >= M, hook_length >= M, hook_width >= M]).
size_constraint(stick, min_wall_m(M), [handle_width >= M]).

%   The strength check of a created tool (creative_py/fabrication/strength.py): a handle
%   at least W wide (its square section bends less), from the largest force the
%   physics put on the tool and a cantilever model of the handle.
size_constraint(hook, min_handle_width_m(W), [handle_width >= W]).
size_constraint(stick, min_handle_width_m(W), [handle_width >= W]).
