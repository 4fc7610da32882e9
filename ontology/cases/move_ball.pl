/*  The move_ball case: RoboToolBench's MoveBall (VLMgineer, arXiv 2507.12644;
    worlds/move_ball/).  The Panda holds a pusher, lowers its walled head round a ball
    lying on the table and sweeps it along -y to a goal, where the ball must end at
    rest (the verdict is the benchmark's reward, measured by the physics).

    Plain Prolog data loaded into this case's own module (case/1 names it), which sees
    the pusher kind's module, the goal zone's (ontology/apparatus/goal_zone.pl: the
    goal disc, in_zone/2, out_of_zone/2, the positioning skill) and the shared files.
*/

case(move_ball).

case_apparatus(move_ball, goal_zone).

case_tool_class(move_ball, pusher).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

task_roles(move_ball, ball1, goal1).

case_goal(move_ball, [in_zone(ball1, goal1)]).

case_skills(move_ball, [pick_up, position_tool, push]).

%   push(T, B, Zone): sweep the held pusher along -y to the goal and wait.
innate_skill(move_ball, push,
             action_model(push, [T-tool, _B-target, _Zone-site],
                          [holding(T)],
                          [],
                          [spatial_of(T)])).

learned_action_names(move_ball, [name(push, in_zone, move_in)]).

                 /*******************************
                 *     POSE                     *
                 *******************************/

/*  The pose term cage_pose(Dx, Dy) (metres): the middle of the room the head's walls
    enclose minus the ball's centre, along x and y.  The push runs along -y.
*/
%   around: the ball inside the head's room, its walls clear of the ball.
spatial_definition(move_ball, around(tool, target), cage_pose(Dx, Dy),
                   [Dx >= -centre_room, Dx =< centre_room,
                    Dy >= -centre_room, Dy =< centre_room]).
%   behind: the head wholly behind the ball (+y), clear of it.
spatial_definition(move_ball, behind(tool, target), cage_pose(_Dx, Dy),
                   [Dy >= ball_radius + head_half + clearance, Dy =< dy_room]).
%   beside: the head's middle off the ball's centre along x by more than the room.
spatial_definition(move_ball, beside(tool, target), cage_pose(Dx, _Dy),
                   [Dx >= ball_radius + clearance, Dx =< dx_room]).

pose_domain(move_ball, cage_pose(Dx, Dy),
            [Dx >= -dx_room, Dx =< dx_room, Dy >= -dy_room, Dy =< dy_room]).

geometry_default(move_ball, ball_radius, 0.08, 'the ball''s radius (RoboToolBench: 0.08 m)').
geometry_default(move_ball, head_half, 0.11, 'half the head''s plate across').
geometry_default(move_ball, centre_room, 0.01, 'how far the head''s middle may lie off the ball''s centre, m').
geometry_default(move_ball, clearance, 0.01, 'clearance between the walls and the ball').
geometry_default(move_ball, dx_room, 0.2, 'bound of Dx either side of the ball').
geometry_default(move_ball, dy_room, 0.25, 'bound of Dy either side of the ball').

geometry_value(move_ball, head_half, Tool, _Target, _G, V) :-
    nonvar(Tool),
    plate_width_m(Tool, W),
    V is W / 2.
geometry_value(move_ball, ball_radius, _Tool, Target, _G, V) :-
    nonvar(Target),
    size(Target, Sx, _, _),
    V is Sx / 2.

%   No reach relation: whether the arm carries a pusher round the ball is the physics'.
reach_definition(move_ball, cage_pose(_, _), []).

relative_pose(move_ball, Tool, Target, _G, cage_pose(Dx, Dy)) :-
    tip_position(Tool, TX, TY, _),
    pose(Target, CX, CY, _, _),
    Dx is TX - CX,
    Dy is TY - CY.

%   pose_target: tip(X, Y, Roll), the head's middle over the table, head down.
pose_target(move_ball, cage_pose(Dx, Dy), Target, _G, tip(X, Y, 0.0)) :-
    pose(Target, CX, CY, _, _),
    X is CX + Dx,
    Y is CY + Dy.

                 /*******************************
                 *     SIZING A NEW TOOL        *
                 *******************************/

%   A new pusher's plate is wider than the ball with room either side.
size_constraint(pusher, reach_zone(_, _, _, _), [plate_width >= min_plate_m]).

size_parameter(min_plate_m, 0.20, 'a head wide enough to close round the 0.16 m ball').
