:- module(abstract_state,
          [ abstract_state/3,         % +Case, +PrimitiveFacts, -Abstract
            pose_numbers/4,           % +Case, +Tool, +PrimitiveFacts, -Pose
            pose_world/5              % +Case, +Tool, +PrimitiveFacts, +Pose, -World
          ]).

/** <module> Primitive state facts to abstract (qualitative) states

A primitive state is a list of ground facts in world coordinates (metres, radians):
camera poses and sizes, the robot's proprioception of the held tool, the catalogue of
available objects and the task geometry (the shared vocabulary of ontology/world.pl).  The
abstract state is the list of qualitative literals that hold in it:

  - *structural* literals of every catalogued object (tool/1, handle_length/2,
    shape/2, ...), by the ontology's rules and qualitative ranges;
  - *task* literals (in_tube(cube1, tube1), door_open(door1), ...), by the case's task
    rules;
  - *spatial* literals of each tool in use with respect to the task's target, by the
    case's spatial definitions evaluated on the pose numbers (pose_numbers/4).

Everything about a case comes from its ontology file (ontology/cases/<case>.pl) through
these hook predicates (case.pl says how a missing one is reported).  "Proved on the
state" means proved by case:case_prove/2 with the primitive facts of the state:

  - case_tool_class(?Case, ?Class): the case's tools belong to the hierarchy Class
    (hook_like, block); its structural literals are those of
    structural_predicate(?Class, ?Name/Arity) (ontology/kinds/<class>.pl).
  - task_predicate(?Case, ?Name/Arity): a task literal of the case, proved on the
    state.
  - tool_in_use(?Case, ?Tool), proved on the state: Tool has spatial literals (the
    hook: a held tool whose tip is inside the tube; the wedge: a held block or one lying
    in the door's sweep).
  - relative_pose(?Case, ?Tool, ?Target, +Geometry, -Pose), proved on the state: the
    pose term of Tool relative to Target (hook_pose(Dx, Dy, Roll), wedge_pose(R, Gap,
    Yaw)); Geometry is geometry_clp:pose_geometry/5's list.
  - pose_target(?Case, +Pose, ?Target, +Geometry, -World), proved on the state: the
    inverse, the world-frame target of the ground pose Pose (tip(X, Y, Roll),
    place(X, Y, Heading)).

The facts are never asserted: they travel in the argument.
*/

:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(case).
:- use_module(geometry_clp).

%!  abstract_state(+Case, +PrimitiveFacts:list, -Abstract:list) is det.
%
%   Abstract is the sorted, duplicate-free list of qualitative literals that hold in the
%   primitive state PrimitiveFacts of Case (a case of ontology/cases/, e.g. hook).
%
%   @error existence_error(case, Case) for a case no ontology file declares.
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
    must_be_case(Case),
    must_be(list, Facts),
    maplist(must_be(ground), Facts),
    findall(L, structural_literal_(Case, Facts, L), Structural),
    findall(L, task_literal_(Case, Facts, L), Task),
    findall(L, spatial_literal_(Case, Facts, L), Spatial),
    append([Structural, Task, Spatial], All),
    sort(All, Abstract).

structural_literal_(Case, Facts, Literal) :-
    case_holds(case_tool_class(Case, Class)),
    class_holds(structural_predicate(Class, N/A)),
    functor(Literal, N, A),
    case_prove(Case, Literal, Facts).

task_literal_(Case, Facts, Literal) :-
    case_holds(task_predicate(Case, N/A)),
    functor(Literal, N, A),
    case_prove(Case, Literal, Facts).

spatial_literal_(Case, Facts, Literal) :-
    case_roles(Case, Target, Context),
    tools_in_use_(Case, Facts, Tools),
    member(Tool, Tools),
    pose_geometry(Case, Tool, Target, Facts, Geometry),
    relative_pose_(Case, Tool, Target, Facts, Geometry, Pose),
    spatial_templates_(Case, Templates),
    member(Template, Templates),
    role_literal_(Template, Tool, Target, Context, Literal),
    spatial_holds(Case, Literal, Pose, Geometry).

%   The tools in use, each once, in the order the case's rules find them.
tools_in_use_(Case, Facts, Tools) :-
    findall(T, case_prove(tool_in_use(Case, T), Facts), Tools0),
    list_to_set(Tools0, Tools).

relative_pose_(Case, Tool, Target, Facts, Geometry, Pose) :-
    findall(P, once(case_prove(relative_pose(Case, Tool, Target, Geometry, P), Facts)),
            [Pose]).

spatial_templates_(Case, Templates) :-
    findall(T, case_holds(spatial_definition(Case, T, _, _)), Ts),
    list_to_set(Ts, Templates).

role_literal_(Template, Tool, Target, Context, Literal) :-
    Template =.. [N|Roles],
    maplist(role_object_(Tool, Target, Context), Roles, Objects),
    Literal =.. [N|Objects].

role_object_(Tool, _, _, tool, Tool).
role_object_(_, Target, _, target, Target).
role_object_(_, _, Context, context, Context).

%!  pose_numbers(+Case, +Tool, +PrimitiveFacts:list, -Pose) is semidet.
%
%   Pose is the pose of Tool relative to the task's target, computed from the
%   primitive facts by the case's relative_pose/5; fails if a needed fact is missing.
%
%   Hook: hook_pose(Dx, Dy, Roll) with Dx = TipX - CubeX, Dy = TipY - CubeY (metres,
%   from tip_position/4 and the cube's pose/5) and Roll from tool_roll/2 (radians,
%   0 = prong down).  Wedge: wedge_pose(R, Gap, Yaw) from the hinge, the door and the
%   wedge's pose and size (ontology/cases/wedge.pl).
%
%   ==
%   ?- pose_numbers(wedge, w, [hinge(door1, 0.0, 0.0), door_closed_heading(door1, 0.0),
%                              door_angle(door1, 0.5), pose(w, 0.6, 0.1, 0.0, 1.74),
%                              size(w, 0.15, 0.05, 0.03)], P).
%   P = wedge_pose(0.6082762530298219, 0.10868210782431094, 0.004054995790476523).
%   ==
pose_numbers(Case, Tool, Facts, Pose) :-
    case_roles(Case, Target, _),
    must_be(list, Facts),
    pose_geometry(Case, Tool, Target, Facts, Geometry),
    relative_pose_(Case, Tool, Target, Facts, Geometry, Pose).

%!  pose_world(+Case, +Tool, +PrimitiveFacts:list, +Pose, -World) is semidet.
%
%   World is where the ground relative pose Pose (e.g. from geometry_clp:solve_pose/5)
%   puts Tool in the world frame, the inverse of pose_numbers/4 in the current state
%   PrimitiveFacts, by the case's pose_target/5; fails if a needed fact is missing.
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
    case_roles(Case, Target, _),
    must_be(list, Facts),
    must_be(ground, Pose),
    pose_geometry(Case, Tool, Target, Facts, Geometry),
    findall(W, once(case_prove(pose_target(Case, Pose, Target, Geometry, W), Facts)),
            [World]).
