:- begin_tests(rlgg).

%   Muggleton & Feng (1990); Lavrac & Dzeroski (1994), Inductive Logic
%   Programming, section 2.2: the RLGG of daughter(mary, ann) and
%   daughter(eve, tom) relative to the family facts is
%   daughter(X, Y) :- female(X), parent(Y, X).
family_bk([ parent(ann, mary), parent(ann, tom), parent(tom, eve),
            parent(tom, ian), female(ann), female(mary), female(eve) ]).

test(daughter, [true(C =@= (daughter(X, Y) :- parent(Y, X), female(X)))]) :-
    family_bk(BK),
    rlgg(daughter(mary, ann), daughter(eve, tom), BK, C).

test(daughter_depth_one, [true(C =@= (daughter(X, Y) :- parent(Y, X), female(X)))]) :-
    family_bk(BK),
    rlgg(daughter(mary, ann), daughter(eve, tom), BK, C, [depth(1)]).

%   Depth 0 saturates with nothing: only the head generalises.
test(depth_zero, [true(C =@= daughter(_, _))]) :-
    family_bk(BK),
    rlgg(daughter(mary, ann), daughter(eve, tom), BK, C, [depth(0)]).

test(saturation_depth_one, [true(C == (daughter(mary, ann) :- parent(ann, mary),
                                       parent(ann, tom), female(ann), female(mary)))]) :-
    family_bk(BK),
    saturate(daughter(mary, ann), BK, C, [depth(1)]).

test(saturation_depth_two_reaches_grandchildren,
     [true(C == (daughter(mary, ann) :- parent(ann, mary), parent(ann, tom),
                 parent(tom, eve), parent(tom, ian), female(ann), female(mary)))]) :-
    family_bk(BK),
    saturate(daughter(mary, ann), BK, C, [depth(2)]).

%   female(eve) is three steps away: ann, then tom, then eve.
test(saturation_depth_three,
     [true(C == (daughter(mary, ann) :- parent(ann, mary), parent(ann, tom),
                 parent(tom, eve), parent(tom, ian), female(ann), female(mary),
                 female(eve)))]) :-
    family_bk(BK),
    saturate(daughter(mary, ann), BK, C, [depth(3)]).

test(saturation_leaves_out_the_example, [true(C == (d(a) :- p(a, b)))]) :-
    saturate(d(a), [d(a), p(a, b)], C, []).

test(numbers_do_not_link, [true(C == (d(a) :- len(a, 0.3)))]) :-
    saturate(d(a), [len(a, 0.3), len(z, 0.3)], C, []).

test(numbers_link_on_request, [true(C == (d(a) :- len(a, 0.3), len(z, 0.3)))]) :-
    saturate(d(a), [len(a, 0.3), len(z, 0.3)], C, [link_numbers(true)]).

%   Hook case: numbers of the two examples become a range; the shared
%   objects cube1 and tube1 stay constants.
test(hook_rlgg,
     [true(C =@= (tool_pose(T, cube1, tube1) :- in_tube(T, tube1), behind(T, cube1),
                  handle_length_m(T, L), in_range(L, 0.35, 0.5)))]) :-
    BK = [ in_tube(hook_a2, tube1), behind(hook_a2, cube1), handle_length_m(hook_a2, 0.35),
           in_tube(hook_a3, tube1), behind(hook_a3, cube1), handle_length_m(hook_a3, 0.5),
           colour(table1, brown) ],
    rlgg(tool_pose(hook_a2, cube1, tube1), tool_pose(hook_a3, cube1, tube1), BK, C).

test(non_ground_example, [error(instantiation_error)]) :-
    rlgg(daughter(_, ann), daughter(eve, tom), [], _).

test(non_ground_fact, [error(instantiation_error)]) :-
    rlgg(daughter(mary, ann), daughter(eve, tom), [female(_)], _).

test(bad_depth, [error(type_error(nonneg, -1))]) :-
    rlgg(daughter(mary, ann), daughter(eve, tom), [], _, [depth(-1)]).

:- end_tests(rlgg).
