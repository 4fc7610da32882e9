/*  Sizing new tools: which spec field each structural property constrains, and the
    margins of the task geometry.

    Plain Prolog data loaded into the knowledge base by knowledge:load_ontology/1 and
    read by geometry_clp:size_constraints/4.  Field names are those of HookSpec and
    BlockSpec in creative_py/mesh/spec.py (metres, hook_angle_deg in degrees).
*/

%   size_field(?Kind, ?Field, ?Property): the spec field Field of a tool of kind Kind is
%   the number behind the qualitative Property (qualitative_range/5), in this order.
size_field(hook, handle_length, handle_length).
size_field(hook, handle_width, handle_width).
size_field(hook, hook_length, hook_length).
size_field(hook, hook_width, hook_width).
size_field(hook, hook_angle_deg, hook_angle).
size_field(stick, handle_length, handle_length).
size_field(stick, handle_width, handle_width).
size_field(block, length, block_length).
size_field(block, width, block_width).
size_field(block, height, block_height).

%   size_choice(?Kind, ?Field, ?Property, ?Values): a field with symbolic values, the
%   values tried in this order when no literal fixes it.
size_choice(hook, hook_side, hook_side, [right, left]).
size_choice(block, shape, shape, [triangular_prism, box, cylinder]).

%   size_parameter(?Name, ?Value, ?Meaning): margins used by the task constraints
%   (metres); a context fact Name(Value) overrides the value.
size_parameter(reach_margin_m, 0.05,
               'handle length beyond the tube length: the grip and the gripper stay outside the mouth').
size_parameter(tube_clearance_m, 0.005,
               'free space left between the tool cross-section and the tube walls').
