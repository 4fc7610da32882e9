/*  Blocks: the object hierarchy, the rules that turn the catalogue (metres) into
    qualitative structural literals, and the size model of a new block.

    Plain Prolog data loaded by knowledge:load_ontology/1 into its own module
    (kind_block, named by the kind/1 fact below).  A case
    whose tools are blocks says so with case_tool_class(Case, block).

        object
        └── block                     block_length, block_width, block_height,
            │                         mechanical_advantage (= length / height)
            ├── triangular_prism      the wedge: thin edge (tip) at +length/2
            ├── box
            └── cylinder              upright; length = width = diameter
*/

%   This file is the kind block: its clauses load into their own module (kind_block),
%   seen by the cases whose case_tool_class/2 names it.
kind(block).

% The hierarchy (object is its root: object(O) marks O as a catalogued object).
subclass_of(block, object).
subclass_of(triangular_prism, block).
subclass_of(box, block).
subclass_of(cylinder, block).

class_property(block, shape).
class_property(block, block_length).
class_property(block, block_width).
class_property(block, block_height).
class_property(block, mechanical_advantage).

primitive_predicate(object_kind/2).
primitive_predicate(block_shape/2).
primitive_predicate(block_length_m/2).
primitive_predicate(block_width_m/2).
primitive_predicate(block_height_m/2).

catalogue_predicate(block, object_kind/2).
catalogue_predicate(block, block_shape/2).
catalogue_predicate(block, block_length_m/2).
catalogue_predicate(block, block_width_m/2).
catalogue_predicate(block, block_height_m/2).

structural_predicate(block, object/1).
structural_predicate(block, block/1).
structural_predicate(block, shape/2).
structural_predicate(block, block_length/2).
structural_predicate(block, block_width/2).
structural_predicate(block, block_height/2).
structural_predicate(block, mechanical_advantage/2).

object(W) :-
    block(W).

block(W) :-
    object_kind(W, block).

shape(W, Shape) :-
    block(W),
    block_shape(W, Shape),
    subclass_of(Shape, block).

block_length(W, Value) :-
    block(W),
    block_length_m(W, L),
    qualitative_value(block_length, L, Value).

block_width(W, Value) :-
    block(W),
    block_width_m(W, L),
    qualitative_value(block_width, L, Value).

block_height(W, Value) :-
    block(W),
    block_height_m(W, H),
    qualitative_value(block_height, H, Value).

%   The paper's "length/width" ratio: its width is the wedge's thickness, our height.
mechanical_advantage(W, Value) :-
    block(W),
    block_length_m(W, L),
    block_height_m(W, H),
    H > 0,
    Ratio is L / H,
    qualitative_value(mechanical_advantage, Ratio, Value).

%   new_tool_kind(?Class, +Structural, -Kind): a new block is sized as a block.
new_tool_kind(block, _, block).

                 /*******************************
                 *     SIZING A NEW BLOCK       *
                 *******************************/

%   Field names are those of BlockSpec in creative_py/mesh/spec.py (metres).
%   tip_height is the height of a prism's blunted tip (x = +length/2): the prism is a
%   trapezoid in side view, so that no part of it is thinner than a printer can print.
size_field(block, length, block_length).
size_field(block, width, block_width).
size_field(block, height, block_height).
size_field(block, tip_height, tip_height).

size_choice(block, shape, shape, [triangular_prism, box, cylinder]).

%   size_choice_constraint(?Field, ?Value, ?Constraints): the constraints a symbolic
%   field's value adds (an upright cylinder is as wide as it is long).  A new prism's
%   tip is blunted, at least min_tip_height_m high and lower than its back; a box or a
%   cylinder has no tip.
size_choice_constraint(shape, cylinder, [width =:= length, tip_height =:= 0]).
size_choice_constraint(shape, box, [tip_height =:= 0]).
size_choice_constraint(shape, triangular_prism,
                       [tip_height >= min_tip_height_m, tip_height < height]).

size_parameter(min_tip_height_m, 0.0008,
               'lowest tip of a new wedge: two 0.4 mm nozzle widths, the thinnest section a printer lays down').

%   size_ratio(?Kind, ?Property, ?Numerator, ?Denominator): Property is the ratio of two
%   fields, its qualitative ranges bound Numerator / Denominator.
size_ratio(block, mechanical_advantage, length, height).

size_constraint(block, max_tool_length(M), [length =< M, width =< M]).
size_constraint(block, min_wall_m(M), [length >= M, width >= M, height >= M]).
