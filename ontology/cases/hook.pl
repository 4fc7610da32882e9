/*  The hook case (paper, case 1): pull a cube out of a closed tube with a hook-like
    tool.  Everything the engine knows about this case is here; the engine asks for it
    through the hook predicates of ontology/README.md ("Hook predicates").

    Plain Prolog data loaded by knowledge:load_ontology/1 into this case's own module
    (case/1 below names it), which sees its tool kind's module, the tube's
    (ontology/apparatus/tube.pl, case_apparatus/2 below) and the shared files: a
    helper predicate here is this case's alone.  Rules marked "proved on the state"
    are proved by case:case_prove/2: their
    primitive facts (pose/5, tube_mouth/4, ...) come from the state the engine hands
    over, never from the database.

    The apparatus: a tube whose axis runs along +x from its mouth, the cube (cube1) lying
    inside it, the tool's prong reaching behind the cube to pull it out.
*/

case(hook).

%   The case's tools are hook-like (ontology/kinds/hook_like.pl): their structural
%   literals, catalogue and size models come from that hierarchy.
case_tool_class(hook, hook_like).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

%   task_roles(?Case, ?Target, ?Context): the object the tool acts on and the object or
%   place the action happens in (the world files' names).
task_roles(hook, cube1, tube1).

case_goal(hook, [out_of_tube(cube1, tube1)]).

%   The tube, its perception, its task literals (in_tube/2, out_of_tube/2), the
%   skills that work in it (position_tool, pull) and its geometry are the tube's,
%   written once in ontology/apparatus/tube.pl and shared with the paddle case.
case_apparatus(hook, tube).

                 /*******************************
                 *     POSE                     *
                 *******************************/

/*  The pose term hook_pose(Dx, Dy, Roll) (metres, metres, radians):
        Dx   prong centre minus cube centre along the tube axis (+x, away from the robot)
        Dy   lateral offset of the handle axis from the cube centre (+y)
        Roll rotation about the handle axis, 0 = prong down, +-pi/2 = prong flat

    spatial_definition(?Case, ?Literal, ?PoseTerm, ?Constraints): Literal holds when
    every linear comparison of Constraints holds for the numbers of PoseTerm; several
    clauses are alternatives.  Literal's arguments are the roles tool, target, context.
    The complement of a clause tries its comparisons in the order written: the first is
    the meaningful "other side".  The prong must clear the cube (half its size plus half
    the prong's thickness plus 5 mm) and stay inside the tube (dx_min .. dx_max).
*/
spatial_definition(hook, in_tube(tool, context), hook_pose(Dx, Dy, _Roll),
                   [Dx =< dx_max, Dx >= dx_min, Dy =< dy_max, Dy >= dy_min]).
spatial_definition(hook, behind(tool, target), hook_pose(Dx, _Dy, _Roll),
                   [Dx >= cube_half + prong_half + clearance, Dx =< dx_max]).
spatial_definition(hook, in_front(tool, target), hook_pose(Dx, _Dy, _Roll),
                   [Dx =< -(cube_half + prong_half + clearance), Dx >= dx_min]).
spatial_definition(hook, centred_on(tool, target), hook_pose(_Dx, Dy, _Roll),
                   [Dy =< 0.005, Dy >= -0.005]).
spatial_definition(hook, hook_down(tool), hook_pose(_Dx, _Dy, Roll),
                   [Roll =< 0.35, Roll >= -0.35]).
spatial_definition(hook, hook_flat(tool), hook_pose(_Dx, _Dy, Roll),
                   [Roll >= 1.2]).
spatial_definition(hook, hook_flat(tool), hook_pose(_Dx, _Dy, Roll),
                   [Roll =< -1.2]).

%   spatial_meaning(?Case, ?Template, ?Meaning): what a spatial relation means across
%   cases (prolog/transfer.pl: a prior's literal transfers to a case that gives its own
%   relation the same meaning).  working_part_down(tool): the tool's working part (a
%   prong, a blade) turned down across the pull's path, roll within 0.35 rad of it.
spatial_meaning(hook, hook_down(tool), working_part_down(tool)).

%   pose_domain(?Case, ?PoseTerm, ?Constraints): where a pose can be at all.  The roll
%   stays within +-pi/2 (prong down to prong flat on either side): a prong rolled
%   further points up, away from anything it could pull, and the arm's insertion motion
%   is planned for that range.
pose_domain(hook, hook_pose(Dx, Dy, Roll),
            [Dx >= -tube_length, Dx =< tube_length, Dy >= -dy_room, Dy =< dy_room,
             Roll >= -pi/2, Roll =< pi/2]).

%   geometry_default(?Case, ?Name, ?Value, ?Meaning): the geometry parameters, with the
%   values used when the state does not give them (metres), in the order they are
%   computed: a parameter's geometry_value/6 rule sees those listed before it.
geometry_default(hook, cube_half, 0.015, 'half the cube side (3 cm cube)').
geometry_default(hook, prong_half, 0.005, 'half the prong thickness along the handle (1 cm prong)').
geometry_default(hook, clearance, 0.005, 'clearance between prong and cube').
geometry_default(hook, handle_half, 0.005, 'half the handle width (1 cm handle)').
geometry_default(hook, tube_length, 0.30, 'tube length (inner)').
geometry_default(hook, dy_room, 0.10, 'lateral bound of any hook pose').
geometry_default(hook, dx_max, 0.07, 'room behind the cube centre to the tube end, minus half the prong').
geometry_default(hook, dx_min, -0.25, 'mouth to cube centre, negated, plus half the prong').
geometry_default(hook, dy_max, 0.01, 'largest Dy keeping the handle in the tube: tube axis minus cube centre, plus inner half width minus handle half width minus clearance').
geometry_default(hook, dy_min, -0.01, 'smallest Dy keeping the handle in the tube').
geometry_default(hook, reach_loss, -0.04, 'handle length the held tool cannot put beyond the mouth: the grip offset less how far the gripper enters the tube (negative: the gripper enters deeper than the grip offset)').
geometry_default(hook, dx_reach, 1.0, 'deepest prong centre the held tool reaches, minus the cube centre (1 m, no bound, when its handle is not known)').

%   geometry_value(?Case, ?Name, ?Tool, ?Target, +Geometry, -Value), proved on the
%   state: the parameter's value from the facts.  Tool and Target may be unbound (then
%   only facts naming neither are used).  cube_half and tube_length are the tube's
%   (ontology/apparatus/tube.pl); the prong stays inside the tube: from the mouth to the
%   far end, relative to the cube.
geometry_value(hook, prong_half, Tool, _Target, _G, V) :-
    nonvar(Tool),
    prong_half_m(Tool, V).
geometry_value(hook, handle_half, Tool, _Target, _G, V) :-
    nonvar(Tool),
    handle_width_m(Tool, W),
    V is W / 2.
geometry_value(hook, dx_max, _Tool, Target, G, V) :-
    memberchk(prong_half=PH, G),
    tube_dx_max(Target, PH, V).
geometry_value(hook, dx_min, _Tool, Target, G, V) :-
    memberchk(prong_half=PH, G),
    tube_dx_min(Target, PH, V).
geometry_value(hook, dy_max, _Tool, Target, G, V) :-
    memberchk(handle_half=HH, G),
    memberchk(clearance=C, G),
    tube_dy_max(Target, HH, C, V).
geometry_value(hook, dy_min, _Tool, Target, G, V) :-
    memberchk(handle_half=HH, G),
    memberchk(clearance=C, G),
    tube_dy_min(Target, HH, C, V).

%   How deep the held tool reaches (reach_definition/3, read only before a tool is
%   tried in a harder task): the prong's centre at most the handle's length, less
%   reach_loss and half the prong, beyond the mouth.  reach_loss is the grip's
%   distance from the butt end (0.04 m, creative_py/mesh/spec.py) less how far the
%   gripper can follow the handle into the mouth.  Measured in the 0.45 m tube,
%   location 1, prong 3 cm behind the cube: handles of 0.36 and 0.38 m fail, 0.40,
%   0.43 and 0.46 m succeed, so the prong reaches about 3 cm beyond the handle's
%   length past the mouth (reach_loss about -0.03 m).  The value, -0.04 m, keeps the
%   reach on the generous side: a pose is called unreachable only where the physics
%   cannot reach it.
reach_definition(hook, hook_pose(Dx, _Dy, _Roll), [Dx =< dx_reach]).

geometry_value(hook, dx_reach, Tool, Target, G, V) :-
    nonvar(Tool),
    handle_length_m(Tool, L),
    memberchk(prong_half=PH, G),
    memberchk(reach_loss=Loss, G),
    tube_dx_reach(Tool, Target, L, PH, Loss, V).

%   relative_pose(?Case, ?Tool, ?Target, +Geometry, -Pose), proved on the state: the
%   held tool's pose relative to the cube (ontology/world.pl's tip_relative_pose/5: the
%   tip's position and the roll against the cube's pose).
relative_pose(hook, Tool, Target, _G, hook_pose(Dx, Dy, Roll)) :-
    tip_relative_pose(Tool, Target, Dx, Dy, Roll).

%   pose_target(?Case, +Pose, ?Target, +Geometry, -World), proved on the state: where
%   the pose puts the tool in the world, tip(X, Y, Roll): the prong centre's world X
%   and Y (its height is the skill's choice) and the roll.
pose_target(hook, hook_pose(Dx, Dy, Roll), Target, _G, tip(X, Y, Roll)) :-
    tip_pose_target(Dx, Dy, Target, X, Y).

                 /*******************************
                 *     SIZING A NEW TOOL        *
                 *******************************/

%   The tube bounds a new hook-like tool (ontology/kinds/hook_like.pl has the rest).
%   The handle reaches behind a cube at the tube's far end with the gripper outside;
%   the tool turns inside the tube.  Keyed by the size kind (hook, stick), these facts
%   are still the hook case's own: they live in its module, so they size the tools of
%   this case only (the rake has its own reach_margin_m).
size_constraint(hook, tube_length_m(_, L), [handle_length >= L + reach_margin_m]).
size_constraint(stick, tube_length_m(_, L), [handle_length >= L + reach_margin_m]).
size_constraint(hook, tube_inner_m(_, W, H),
                [handle_width + hook_length =< min(W, H) - tube_clearance_m]).
size_constraint(stick, tube_inner_m(_, W, H),
                [handle_width =< min(W, H) - tube_clearance_m]).

%   The margins reach_margin_m and tube_clearance_m are the tube's
%   (ontology/apparatus/tube.pl, size_parameter/3).
