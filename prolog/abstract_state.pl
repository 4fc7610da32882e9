:- module(abstract_state,
          [ abstract_state/3,         % +Case, +PrimitiveFacts, -Abstract
            pose_numbers/4,           % +Case, +Tool, +PrimitiveFacts, -Pose
            pose_world/5              % +Case, +Tool, +PrimitiveFacts, +Pose, -World
          ]).

/** <module> Primitive state facts to abstract (qualitative) states

A primitive state is a list of ground facts in world coordinates (metres, radians):
camera poses and sizes, the robot's proprioception of the held tool, the catalogue of
available objects and the task geometry (shared vocabulary, DESIGN.md §3).  The
abstract state is the list of qualitative literals that hold in it:

  - *structural* literals of every catalogued object (tool/1, handle_length/2,
    shape/2, ...), by the ontology's rules and qualitative ranges;
  - *task* literals (in_tube(cube1, tube1), out_of_tube/2, door_open/1, door_held/1),
    by the ontology's task rules;
  - *spatial* literals of each tool in use with respect to the task's target, by the
    ontology's spatial definitions evaluated on the pose numbers (pose_numbers/4).

Tools in use: in the hook case every held(T) tool whose tip lies inside the tube's
inner box (so the tube's facts tube_mouth/4, tube_length_m/2 and tube_inner_m/3 must be
given for any hook spatial literal); in the wedge case every held block and
every block that lies in the door's sweep (0 =< Phi =< A, R =< door width).

The ontology is read from the knowledge base (knowledge:load_default_ontology/0); the
facts are never asserted: they travel in the argument.
*/

:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(knowledge).
:- use_module(geometry_clp).

%!  abstract_state(+Case, +PrimitiveFacts:list, -Abstract:list) is det.
%
%   Abstract is the sorted, duplicate-free list of qualitative literals that hold in the
%   primitive state PrimitiveFacts of Case (hook or wedge).
%
%   @error type_error(list, F) if PrimitiveFacts is not a list;
%          instantiation_error if a fact is not ground.
%
%   ==
%   ?- abstract_state(hook, [object_kind(h, hook), handle_length_m(h, 0.3),
%                            tube_mouth(tube1, 0.7, 0.0, 0.0), tube_length_m(tube1, 0.3),
%                            tube_inner_m(tube1, 0.08, 0.07),
%                            held(h), tip_position(h, 0.95, 0.0, 0.0), tool_roll(h, 0.1),
%                            pose(cube1, 0.9, 0.0, -0.01, 0.0), size(cube1, 0.03, 0.03, 0.03)], A).
%   A = [hook(h), hook_down(h), hook_like(h), tool(h), behind(h, cube1),
%        centred_on(h, cube1), handle_length(h, medium), in_tube(cube1, tube1),
%        in_tube(h, tube1)].          % standard order: arity first
%   ==
abstract_state(Case, Facts, Abstract) :-
    must_be_oneof_([hook, wedge], Case),
    must_be(list, Facts),
    maplist(must_be(ground), Facts),
    findall(L, derived_literal_(Case, structural_predicate, Facts, L), Structural),
    findall(L, derived_literal_(Case, task_predicate, Facts, L), Task),
    findall(L, spatial_literal_(Case, Facts, L), Spatial),
    append([Structural, Task, Spatial], All),
    sort(All, Abstract).

derived_literal_(Case, Kind, Facts, Literal) :-
    Decl =.. [Kind, Case, N/A],
    kb_clause(Decl, true),
    functor(Literal, N, A),
    kb_prove(Literal, Facts).

spatial_literal_(Case, Facts, Literal) :-
    once(kb_clause(task_roles(Case, Target, Context), true)),
    tool_in_use_(Case, Facts, Tool),
    pose_numbers(Case, Tool, Facts, Pose),
    pose_geometry(Case, Tool, Target, Facts, Geometry),
    spatial_templates_(Case, Templates),
    member(Template, Templates),
    role_literal_(Template, Tool, Target, Context, Literal),
    spatial_holds(Case, Literal, Pose, Geometry).

spatial_templates_(Case, Templates) :-
    findall(T, kb_clause(spatial_definition(Case, T, _, _), true), Ts),
    list_to_set(Ts, Templates).

role_literal_(Template, Tool, Target, Context, Literal) :-
    Template =.. [N|Roles],
    maplist(role_object_(Tool, Target, Context), Roles, Objects),
    Literal =.. [N|Objects].

role_object_(Tool, _, _, tool, Tool).
role_object_(_, Target, _, target, Target).
role_object_(_, _, Context, context, Context).

tool_in_use_(hook, Facts, Tool) :-
    member(held(Tool), Facts),
    tip_in_tube_(Tool, Facts).
tool_in_use_(wedge, Facts, Tool) :-
    findall(T, member(held(T), Facts), Held),
    findall(W, ( member(object_kind(W, block), Facts),
                 \+ memberchk(W, Held),
                 block_in_sweep_(W, Facts) ),
            Placed),
    append(Held, Placed, Tools),
    member(Tool, Tools).

%   The held tool's tip is inside the tube's inner box.
tip_in_tube_(Tool, Facts) :-
    memberchk(tube_mouth(Tube, MX, MY, MZ), Facts),
    memberchk(tube_length_m(Tube, L), Facts),
    memberchk(tube_inner_m(Tube, W, H), Facts),
    memberchk(tip_position(Tool, X, Y, Z), Facts),
    X >= MX,
    X =< MX + L,
    abs(Y - MY) =< W / 2,
    abs(Z - MZ) =< H / 2.

block_in_sweep_(W, Facts) :-
    once(kb_clause(task_roles(wedge, Door, _), true)),
    door_polar_(W, Door, Facts, R, Phi, A),
    memberchk(door_width_m(Door, Width), Facts),
    R =< Width,
    Phi >= 0,
    Phi =< A.

%!  pose_numbers(+Case, +Tool, +PrimitiveFacts:list, -Pose) is semidet.
%
%   Pose is the pose of Tool relative to the task's target, computed from the
%   primitive facts; fails if a needed fact is missing.
%
%   Hook: hook_pose(Dx, Dy, Roll) with Dx = TipX - CubeX, Dy = TipY - CubeY (metres,
%   from tip_position/4 and the cube's pose/5) and Roll from tool_roll/2 (radians,
%   0 = prong down).
%
%   Wedge: wedge_pose(R, Gap, Yaw) from hinge/3, door_closed_heading/2, door_angle/2
%   and the wedge's pose/5 and size/4 (or block_length_m/2): R is the distance from
%   the hinge to the wedge's centre; Phi the heading of (wedge - hinge) relative to the
%   closed door; Gap = R * (A - Phi) - length / 2 - door half thickness (0.02, from the
%   ontology's geometry_default/4); Yaw the wedge's heading (its tip's direction, +x of
%   the block frame) minus the heading from the wedge towards the closing door (the
%   counter-clockwise tangent, Theta0 + Phi + pi/2), wrapped to (-pi, pi], so that
%   0 = tip pointing at the door.
%
%   ==
%   ?- pose_numbers(wedge, w, [hinge(door1, 0.0, 0.0), door_closed_heading(door1, 0.0),
%                              door_angle(door1, 0.5), pose(w, 0.6, 0.1, 0.0, 1.74),
%                              size(w, 0.15, 0.05, 0.03)], P).
%   P = wedge_pose(0.6082762530298219, 0.10868210782431094, 0.004054995790476523).
%   ==
pose_numbers(Case, Tool, Facts, Pose) :-
    must_be_oneof_([hook, wedge], Case),
    must_be(list, Facts),
    pose_numbers_(Case, Tool, Facts, Pose).

pose_numbers_(hook, Tool, Facts, hook_pose(Dx, Dy, Roll)) :-
    once(kb_clause(task_roles(hook, Target, _), true)),
    memberchk(tip_position(Tool, TX, TY, _), Facts),
    memberchk(tool_roll(Tool, Roll), Facts),
    memberchk(pose(Target, CX, CY, _, _), Facts),
    Dx is TX - CX,
    Dy is TY - CY.
pose_numbers_(wedge, Tool, Facts, wedge_pose(R, Gap, Yaw)) :-
    once(kb_clause(task_roles(wedge, Door, _), true)),
    door_polar_(Tool, Door, Facts, R, Phi, A),
    memberchk(door_closed_heading(Door, Theta0), Facts),
    memberchk(pose(Tool, _, _, _, Heading), Facts),
    pose_geometry(wedge, Tool, Door, Facts, Geometry),
    memberchk(wedge_half=Half, Geometry),
    memberchk(door_half_thickness=Thick, Geometry),
    Gap is R * (A - Phi) - Half - Thick,
    Towards is Theta0 + Phi + pi / 2,
    wrap_angle_(Heading - Towards, Yaw).

%!  pose_world(+Case, +Tool, +PrimitiveFacts:list, +Pose, -World) is semidet.
%
%   World is where the ground relative pose Pose (hook_pose/3 or wedge_pose/3, e.g.
%   from geometry_clp:solve_pose/5) puts Tool in the world frame, the inverse of
%   pose_numbers/4 in the current state PrimitiveFacts; fails if a needed fact is
%   missing.
%
%   Hook: World = tip(X, Y, Roll), the prong centre's world X and Y (metres; its
%   height is the skill's choice) and the roll (radians, 0 = prong down).
%   Wedge: World = place(X, Y, Heading), the wedge centre's world X and Y and the
%   world yaw of its tip (+x of the block frame), radians in (-pi, pi]; the door's
%   opening A is taken from door_angle/2 (the door as it stands when the trial starts).
%
%   ==
%   ?- pose_world(hook, h, [pose(cube1, 0.9, -0.25, -0.0125, 0.0)],
%                 hook_pose(0.04, 0.0, 0.0), W).
%   W = tip(0.9400000000000001, -0.25, 0.0).
%   ==
pose_world(Case, Tool, Facts, Pose, World) :-
    must_be_oneof_([hook, wedge], Case),
    must_be(list, Facts),
    must_be(ground, Pose),
    pose_world_(Case, Tool, Facts, Pose, World).

pose_world_(hook, _Tool, Facts, hook_pose(Dx, Dy, Roll), tip(X, Y, Roll)) :-
    once(kb_clause(task_roles(hook, Target, _), true)),
    memberchk(pose(Target, CX, CY, _, _), Facts),
    X is CX + Dx,
    Y is CY + Dy.
pose_world_(wedge, Tool, Facts, wedge_pose(R, Gap, Yaw), place(X, Y, Heading)) :-
    once(kb_clause(task_roles(wedge, Door, _), true)),
    memberchk(hinge(Door, HX, HY), Facts),
    memberchk(door_closed_heading(Door, Theta0), Facts),
    memberchk(door_angle(Door, A), Facts),
    R > 0,
    pose_geometry(wedge, Tool, Door, Facts, Geometry),
    memberchk(wedge_half=Half, Geometry),
    memberchk(door_half_thickness=Thick, Geometry),
    Phi is A - (Gap + Half + Thick) / R,
    X is HX + R * cos(Theta0 + Phi),
    Y is HY + R * sin(Theta0 + Phi),
    wrap_angle_(Yaw + Theta0 + Phi + pi / 2, Heading).

%   door_polar_(+W, +Door, +Facts, -R, -Phi, -A): W's centre in polar coordinates about
%   the hinge, Phi relative to the closed door's heading, wrapped to (-pi, pi].
door_polar_(W, Door, Facts, R, Phi, A) :-
    memberchk(hinge(Door, HX, HY), Facts),
    memberchk(door_closed_heading(Door, Theta0), Facts),
    memberchk(door_angle(Door, A), Facts),
    memberchk(pose(W, X, Y, _, _), Facts),
    R is sqrt((X - HX)**2 + (Y - HY)**2),
    wrap_angle_(atan2(Y - HY, X - HX) - Theta0, Phi).

wrap_angle_(Expr, Wrapped) :-
    A is Expr,
    W0 is A - 2 * pi * floor((A + pi) / (2 * pi)),
    (   W0 =< -pi
    ->  Wrapped is W0 + 2 * pi
    ;   Wrapped = W0
    ).

%   must_be_oneof_(+Values, +X): X is one of the atoms Values, else a domain error.
must_be_oneof_(Values, X) :-
    must_be(atom, X),
    (   memberchk(X, Values)
    ->  true
    ;   domain_error(oneof(Values), X)
    ).
