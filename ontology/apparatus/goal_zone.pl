/*  The goal zone: a cube (the task's target) lying on a table outside a goal region, a
    disc on the table, and the task of moving the cube into the disc with a held tool
    (ManiSkill3's tabletop tasks: the disc about the robot base of PullCubeTool-v1, the
    goal disc beyond the cube of PokeCube-v1; RoboToolBench's MoveBall and CleanTable on
    pybullet, where a zone body reports the disc and the target is a ball or a field of
    cubes).  Written once for every case that uses it (ontology/cases/pull_cube_tool.pl,
    ontology/cases/poke_cube.pl, ontology/cases/move_ball.pl,
    ontology/cases/clean_table.pl), each naming it by a fact case_apparatus(Case,
    goal_zone).

    Plain Prolog data loaded by knowledge:load_ontology/1 into its own module,
    apparatus_goal_zone (apparatus/1 below names it), which sees the shared files only;
    a case that names it sees this module after its kind's.  A clause whose first
    argument is a variable answers that hook for every case that uses the zone; the
    cases keep what depends on their skill (pushing or pulling), their pose term and
    their tool's parts.  Rules marked "proved on the state" take their primitive facts
    (pose/5, reach_zone/4, ...) from the state the engine hands over, never from the
    database.
*/

apparatus(goal_zone).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

%   Objects a plan needs that no literal of the state names.
case_extra_objects(_, []).

%   position_tool(T, C, Zone): put the held tool at a pose relative to the cube lying
%   outside the zone; which spatial literals become true is the pose's business.
innate_skill(_, position_tool,
             action_model(position_tool, [T-tool, C-target, Zone-site],
                          [holding(T), out_of_zone(C, Zone)],
                          [spatial_of(T)],
                          [spatial_of(T)])).

%   The tool acts while the robot holds it (its spatial literals count when held).
tool_acts_when(_, held).

%   Every spatial literal is a pose choice the trials may test.
untestable_literals(_, []).

                 /*******************************
                 *     STATE                    *
                 *******************************/

%   reach_zone(Zone, X, Y, R): the goal disc's centre (world x, y) and radius (metres).
%   tool_axis_y(Tool, Y): the held tool's handle axis, world y.
primitive_predicate(reach_zone/4).
primitive_predicate(tool_axis_y/2).

task_predicate(_, in_zone/2).
task_predicate(_, out_of_zone/2).

%   in_zone(?Object, ?Zone): an uncatalogued object (the cube) whose centre lies inside
%   the disc.
in_zone(C, Zone) :-
    reach_zone(Zone, ZX, ZY, R),
    pose(C, X, Y, _, _),
    \+ object_kind(C, _),
    (X - ZX)**2 + (Y - ZY)**2 < R**2.

out_of_zone(C, Zone) :-
    reach_zone(Zone, _, _, _),
    pose(C, _, _, _, _),
    \+ object_kind(C, _),
    \+ in_zone(C, Zone).

%   tool_in_use(?Case, ?Tool), proved on the state: a held tool lowered to the table
%   (its tip's centre below 6 cm) has spatial literals.
tool_in_use(_, Tool) :-
    held(Tool),
    tip_position(Tool, _, _, Z),
    Z < 0.06.

                 /*******************************
                 *     POSE                     *
                 *******************************/

%   Half the cube's side, from its perceived size.
geometry_value(_, cube_half, _Tool, Target, _G, V) :-
    nonvar(Target),
    size(Target, Sx, _, _),
    V is Sx / 2.
