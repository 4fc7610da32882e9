/*  The world frame: the primitive facts every case's perception supplies, and the
    angle and pose arithmetic the cases' pose rules share (a target's extent along x,
    a held tool's tip relative to the target and back).

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

%   half_extent_x(+Object, -Half), proved on the state: half the object's extent along
%   the world's x axis, from its perceived size and heading (a box turned by Yaw).
half_extent_x(Object, Half) :-
    size(Object, Sx, Sy, _),
    pose(Object, _, _, _, Yaw),
    Half is (Sx * abs(cos(Yaw)) + Sy * abs(sin(Yaw))) / 2.

%   tip_relative_pose(+Tool, +Target, -Dx, -Dy, -Roll), proved on the state: the held
%   tool's tip minus the target's centre along x and y (proprioception and camera),
%   and the tool's roll: the numbers of a pose term Name(Dx, Dy, Roll).
tip_relative_pose(Tool, Target, Dx, Dy, Roll) :-
    tip_position(Tool, TX, TY, _),
    tool_roll(Tool, Roll),
    pose(Target, X, Y, _, _),
    Dx is TX - X,
    Dy is TY - Y.

%   tip_pose_target(+Dx, +Dy, +Target, -X, -Y), proved on the state: where the pose
%   numbers Dx, Dy put the tool's tip in the world (its height is the skill's choice).
tip_pose_target(Dx, Dy, Target, X, Y) :-
    pose(Target, CX, CY, _, _),
    X is CX + Dx,
    Y is CY + Dy.
