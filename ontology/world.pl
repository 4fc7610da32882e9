/*  The world frame: the primitive facts every case's perception supplies, and the
    angle arithmetic the cases' pose rules share.

    Plain Prolog data loaded into the shared module kb by knowledge:load_ontology/1.
    Primitive facts are in world coordinates (metres, radians); a case declares its own
    apparatus's facts (a tube's mouth, a door's hinge) in its file under ontology/cases/.
*/

%   pose(Object, X, Y, Z, Yaw): an object's centre and heading, from the cameras.
primitive_predicate(pose/5).
%   size(Object, Sx, Sy, Sz): an object's extent along its own axes, from the cameras.
primitive_predicate(size/4).
%   held(Tool): the gripper holds Tool (proprioception).
primitive_predicate(held/1).
%   tip_position(Tool, X, Y, Z): the held tool's working end (proprioception).
primitive_predicate(tip_position/4).
%   tool_roll(Tool, Roll): the held tool's roll about its handle axis, 0 = prong down.
primitive_predicate(tool_roll/2).

%   wrap_angle(+Expr, -Wrapped): the angle Expr (radians) wrapped to (-pi, pi].
wrap_angle(Expr, Wrapped) :-
    A is Expr,
    W0 is A - 2 * pi * floor((A + pi) / (2 * pi)),
    (   W0 =< -pi
    ->  Wrapped is W0 + 2 * pi
    ;   Wrapped = W0
    ).
