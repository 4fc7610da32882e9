/*  Blocks of the wedge case: the object hierarchy and the rules that turn the
    catalogue (metres) into qualitative structural literals.

    Plain Prolog data loaded into the knowledge base by knowledge:load_ontology/1.

        object
        └── block                     block_length, block_width, block_height,
            │                         mechanical_advantage (= length / height)
            ├── triangular_prism      the wedge: thin edge (tip) at +length/2
            ├── box
            └── cylinder              upright; length = width = diameter
*/

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

structural_predicate(wedge, object/1).
structural_predicate(wedge, block/1).
structural_predicate(wedge, shape/2).
structural_predicate(wedge, block_length/2).
structural_predicate(wedge, block_width/2).
structural_predicate(wedge, block_height/2).
structural_predicate(wedge, mechanical_advantage/2).

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
