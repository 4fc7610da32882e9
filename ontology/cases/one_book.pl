/*  The one-book case (RoboToolBench's OneBook: Gao et al., "VLMgineer", arXiv
    2507.12644): five books stand in a row between two bookends; the middle one must be
    pulled out towards the robot without moving the others.  A hook-like tool carried
    over the book, its prong dropped behind the book's back and pulled along -x, draws
    it out.  Everything the engine knows about this case is here, in its own module
    (case_one_book); the engine asks for it through the hook predicates of
    ontology/README.md.  Rules marked "proved on the state" take their primitive facts
    (pose/5, bookends_front/4, ...) from the state the engine hands over.

    The apparatus: a pair of bookends (bookends1) whose base plates carry the row; the
    room above the plates between the uprights is the passage the tool is carried
    through, along +x from the row's front.
*/

case(one_book).
case_tool_class(one_book, hook_like).

                 /*******************************
                 *     TASK AND SKILLS          *
                 *******************************/

task_roles(one_book, book3, bookends1).
case_goal(one_book, [pulled_out(book3, bookends1)]).
case_extra_objects(one_book, []).
case_skills(one_book, [pick_up, position_tool, pull]).

%   position_tool(T, B, E): carry the held tool over the row to a pose relative to the
%   book; pull(T, B, E): draw it back along -x.
innate_skill(one_book, position_tool,
             action_model(position_tool, [T-tool, B-target, E-site],
                          [holding(T), in_row(B, E)],
                          [spatial_of(T)],
                          [spatial_of(T)])).
innate_skill(one_book, pull,
             action_model(pull, [T-tool, _B-target, E-site],
                          [holding(T)],
                          [],
                          [over_row(T, E), spatial_of(T)])).

learned_action_names(one_book, [name(pull, pulled_out, pull_out)]).
tool_acts_when(one_book, held).

%   The tool is always used over the row, never tested elsewhere.
untestable_literals(one_book, [over_row(_, _)]).

                 /*******************************
                 *     STATE                    *
                 *******************************/

%   The bookends (scene body kind bookends): the row's front x, the middle's y and the
%   base plates' top z; the room between the uprights, their height above the plates
%   and the row's depth along x (metres).
primitive_predicate(bookends_front/4).
primitive_predicate(bookends_room_m/4).

task_predicate(one_book, in_row/2).
task_predicate(one_book, pulled_out/2).

%   in_row(?Book, ?Bookends): an uncatalogued object standing in the row.
in_row(B, E) :-
    bookends_front(E, FX, FY, _),
    bookends_room_m(E, W, _, D),
    pose(B, X, Y, _, _),
    \+ object_kind(B, _),
    X >= FX,
    X =< FX + D,
    abs(Y - FY) =< W / 2.

%   pulled_out(?Book, ?Bookends): its centre drawn towards the robot past the
%   benchmark's success distance (half the book's diagonal, 0.147 m) from the row's
%   middle.
pulled_out(B, E) :-
    bookends_front(E, FX, FY, _),
    bookends_room_m(E, W, _, D),
    pose(B, X, Y, _, _),
    \+ object_kind(B, _),
    abs(Y - FY) =< W / 2,
    X < FX + D / 2 - 0.147.

%   tool_in_use(?Case, ?Tool), proved on the state: a held tool whose prong is over the
%   row, beside or behind it, has spatial literals.
tool_in_use(one_book, Tool) :-
    held(Tool),
    bookends_front(E, FX, FY, Z),
    bookends_room_m(E, W, H, D),
    tip_position(Tool, X, Y, TZ),
    X >= FX,
    X =< FX + D + 0.10,
    abs(Y - FY) =< W / 2,
    TZ >= Z,
    TZ =< Z + H + 0.05.

                 /*******************************
                 *     POSE                     *
                 *******************************/

/*  book_pose(Dx, Dy, Roll) (metres, metres, radians): the prong's centre minus the
    book's centre along x and y, and the tool's roll about its handle (0 = prong
    down, +-pi/2 = flat).  Behind: the prong clears the book's back (half its extent
    along x, half the prong, 5 mm); over_row: the prong over the row or just behind it.
*/
spatial_definition(one_book, over_row(tool, context), book_pose(Dx, Dy, _),
                   [Dx =< dx_max, Dx >= dx_min, Dy =< dy_room, Dy >= -dy_room]).
spatial_definition(one_book, behind(tool, target), book_pose(Dx, _, _),
                   [Dx >= book_half + prong_half + clearance, Dx =< dx_max]).
spatial_definition(one_book, in_front(tool, target), book_pose(Dx, _, _),
                   [Dx =< -(book_half + prong_half + clearance), Dx >= dx_min]).
spatial_definition(one_book, centred_on(tool, target), book_pose(_, Dy, _),
                   [Dy =< 0.005, Dy >= -0.005]).
spatial_definition(one_book, hook_down(tool), book_pose(_, _, Roll),
                   [Roll =< 0.35, Roll >= -0.35]).
spatial_definition(one_book, hook_flat(tool), book_pose(_, _, Roll), [Roll >= 1.2]).
spatial_definition(one_book, hook_flat(tool), book_pose(_, _, Roll), [Roll =< -1.2]).

spatial_meaning(one_book, hook_down(tool), working_part_down(tool)).

pose_domain(one_book, book_pose(Dx, Dy, Roll),
            [Dx >= -0.40, Dx =< 0.40, Dy >= -0.10, Dy =< 0.10,
             Roll >= -pi/2, Roll =< pi/2]).

geometry_default(one_book, book_half, 0.14, 'half the book extent along x').
geometry_default(one_book, prong_half, 0.006, 'half the prong thickness along the handle').
geometry_default(one_book, clearance, 0.005, 'clearance between prong and book').
geometry_default(one_book, dy_room, 0.10, 'lateral bound of any pose').
geometry_default(one_book, deep_m, 0.015, 'how far behind the book''s back the prong may go: deeper puts the hand among the books').
geometry_default(one_book, dx_max, 0.161, 'the deepest prong centre behind the book''s centre').
geometry_default(one_book, dx_min, -0.14, 'the row''s front minus the book centre').
geometry_default(one_book, reach_loss, 0.045, 'handle length the held tool cannot put beyond the row''s front: the grip offset and the hand kept in front of the books (measured: the gripper at most 5 mm past the front)').
geometry_default(one_book, dx_reach, 1.0, 'deepest prong centre the held tool reaches, minus the book centre (1 m, no bound, when its handle is not known)').

%   The book's extent along x from its perceived size and heading.
geometry_value(one_book, book_half, _, Target, _, V) :-
    nonvar(Target),
    half_extent_x(Target, V).
geometry_value(one_book, prong_half, Tool, _, _, V) :-
    nonvar(Tool),
    prong_half_m(Tool, V).
geometry_value(one_book, dx_max, _, Target, G, V) :-
    nonvar(Target),
    bookends_front(E, FX, _, _),
    bookends_room_m(E, _, _, D),
    pose(Target, X, _, _, _),
    memberchk(book_half=BH, G),
    memberchk(prong_half=PH, G),
    memberchk(deep_m=Deep, G),
    V is min(FX + D + 0.10 - X, BH + PH + Deep).
geometry_value(one_book, dx_min, _, Target, _, V) :-
    nonvar(Target),
    bookends_front(_, FX, _, _),
    pose(Target, X, _, _, _),
    V is FX - X.

%   How far behind the book the held tool reaches (reach_definition/3, read only before
%   a tool is tried in a harder task): its prong's centre at most the handle's length,
%   less reach_loss and half the prong, beyond the row's front.
reach_definition(one_book, book_pose(Dx, _Dy, _Roll), [Dx =< dx_reach]).

geometry_value(one_book, dx_reach, Tool, Target, G, V) :-
    nonvar(Tool),
    nonvar(Target),
    handle_length_m(Tool, L),
    bookends_front(_, FX, _, _),
    pose(Target, X, _, _, _),
    memberchk(prong_half=PH, G),
    memberchk(reach_loss=Loss, G),
    V is FX + L - Loss - PH - X.

%   The held tool's pose relative to the book (proprioception and camera).
relative_pose(one_book, Tool, Target, _, book_pose(Dx, Dy, Roll)) :-
    tip_relative_pose(Tool, Target, Dx, Dy, Roll).

%   Where a pose puts the prong's centre (x, y) and the roll.
pose_target(one_book, book_pose(Dx, Dy, Roll), Target, _, tip(X, Y, Roll)) :-
    tip_pose_target(Dx, Dy, Target, X, Y).

                 /*******************************
                 *     SIZING A NEW TOOL        *
                 *******************************/

%   The handle reaches over the row's depth with the hand in front of it, and no
%   further: a longer handle puts the hand so near the Panda's base at the books'
%   height that the arm cannot follow the pull.  Measured in the benchmark's row (0.28
%   m deep), prong 1.6 cm behind the book: handles of 0.30 and 0.32 m put the hand
%   among the books (reward 0.965, 0.981: the neighbours moved 35 and 19 mm), 0.34 m
%   pulls the book out alone (0.9995), 0.36 and 0.42 m find no arm posture.
size_constraint(hook, bookends_room_m(_, _, _, D),
                [handle_length >= D + book_reach_margin_m,
                 handle_length =< D + book_reach_margin_m + book_reach_room_m]).
size_constraint(stick, bookends_room_m(_, _, _, D),
                [handle_length >= D + book_reach_margin_m,
                 handle_length =< D + book_reach_margin_m + book_reach_room_m]).

%   A thick handle rides higher over the book, and the hand with it: a 21 mm handle
%   (0.345 m) found no arm posture where 9-10 mm ones pull the book out.
size_constraint(hook, bookends_room_m(_, _, _, _), [handle_width =< book_handle_max_m]).
size_constraint(stick, bookends_room_m(_, _, _, _), [handle_width =< book_handle_max_m]).

size_parameter(book_handle_max_m, 0.012, 'the thickest handle the hand can ride over the books with').
size_parameter(book_reach_margin_m, 0.06,
               'handle length beyond the row''s depth: the grip offset and the prong behind the book, the hand in front of the books').
size_parameter(book_reach_room_m, 0.01,
               'how much longer the handle may be: the arm must still follow the pull towards its base').
