:- module(version_space,
          [ vs_init/2,               % +Example, -VS
            vs_init_prior/3,         % +Example, +PriorLiterals, -VS
            vs_prior/3,              % +VS, -Kept, -Dropped
            vs_prior_events/2,       % +VS, -Events
            vs_prior_open/2,         % +VS, -Positions
            vs_prior_clause/2,       % +VS, -Clause
            vs_update/3,             % +VS0, +LabelledExample, -VS
            vs_bounds/3,             % +VS, -HS, -HG
            vs_unknown/2,            % +VS, -Literals
            vs_examples/3,           % +VS, -Pos, -Neg
            vs_converged/1,          % +VS
            vs_covers/3,             % +VS, +Bound, +Example
            vs_notes/2,              % +VS, -Notes
            vs_space/4,              % +VS, -HS, -Literals, -Constraints
            vs_space_count/5,        % +Literals, +Constraints, +Out, +Priors, -Count-Mass
            vs_space_positions/3,    % +Literals, +Violated, -Positions
            vs_count/3               % +VS, -Count, -Exact
          ]).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(ordsets)).
:- use_module(library(yall)).
:- use_module(lgg, [clause_lgg/3]).
:- use_module(subsumption,
              [ clause_head_body/3, clause_covers/2, clause_violations/3 ]).

/** <module> Version space of a tool-use concept: h_s and h_g

Mitchell's version space as CREATIVE uses it (paper, Algorithm 1): a most
specific hypothesis h_s, generalised by constrained LGG on positives, and a
most general hypothesis h_g, specialised on negatives with literals of h_s
(negative-based reduction style). Examples are ground clauses
`tool_pose(Tool, Target, Context) :- Facts`.

The state is one term (opaque: use the accessors)

    vs(Head, SBody, GBody, Pos, Neg, Notes)

Head is shared by h_s (`Head :- SBody`) and h_g (`Head :- GBody`); Pos and
Neg list the examples in arrival order; Notes lists, newest first, what was
inconsistent:

  - hg_weakened(E, Dropped): the positive E violated the h_g literals
    Dropped, which were removed from h_g.
  - noisy_negative(E): the negative E is covered by h_s, so no literal of h_s
    can exclude it; h_g was left unchanged and E is ignored when h_g is
    specialised later.
  - prior(L, Kind): the literal L of h_s was taken from a prior (vs_init_prior/3);
    Kind is spatial or structural. It starts *open*: a prediction, not in h_g and
    not a constraint of the hypotheses, only likelier necessary for the strategy
    (vs_prior_open/2). The physics decides what becomes of it:
  - prior_settled(L, E): the positive E satisfied the open spatial literal L (a
    success consistent with the prior's relation): L joins h_g and every hypothesis
    keeps it (vs_space/4); the stop is certified relative to it.
  - prior_confirmed(L, E): after the example E, the learned part of h_g holds L (a
    failure made it necessary, as without a prior).
  - prior_dropped(L, E): the positive E violated the prior's literal L (the physics
    contradicted the prior): L left h_g (and, by the LGG, h_s), learned afresh.
  - hg_learned(Body): the part of h_g learned from the examples alone, exactly the
    h_g of the same examples without a prior; h_g is it plus the settled literals.
    A failure is learned from with this part only, so no literal of the prior can
    explain a failure away.

*Free literals.* After an LGG, a literal whose variable occurs nowhere else
in h_s and has no range (e.g. `handle_length(T, L)` from `medium` and
`long`) only says that the tool has some handle length. No experiment can
violate it, so h_s drops it (repeatedly, until no such literal is left). A
positive with a different handle length therefore removes `handle_length/2`
from h_s.

*Ranges.* `in_range(V, Lo, Hi)` literals of h_s (from the constrained LGG of
numbers) belong to the literal that binds V: they are not unknown literals to
test, so vs_unknown/2 leaves them out. When h_g takes a literal of h_s it
takes the range literals of that literal's variables with it.
*/

%!  vs_init(+Example, -VS) is det.
%
%   VS is the version space of the first positive example Example, a
%   ground clause whose head arguments are distinct atoms (the roles:
%   tool, target, context). h_s is Example with each head atom replaced by a
%   fresh variable everywhere in the clause (numbers stay numbers); h_g is
%   the head with an empty body. Raises type_error(clause, Example),
%   instantiation_error for a non-ground example and
%   domain_error(distinct_head_atoms, Head) otherwise.
%
%   ==
%   ?- vs_init((tool_pose(hook_a2, cube1, tube1) :- hook(hook_a2),
%               behind(hook_a2, cube1)), VS), vs_bounds(VS, HS, HG).
%   HS = (tool_pose(T, C, X) :- hook(T), behind(T, C)),
%   HG = tool_pose(T, C, X).
%   ==
vs_init(Example, VS) :-
    clause_head_body(Example, Head0, Body0),
    must_be(ground, Example),
    Head0 =.. [Name|Args],
    (   maplist(atom, Args),
        sort(Args, Sorted),
        length(Args, N),
        length(Sorted, N)
    ->  true
    ;   domain_error(distinct_head_atoms, Head0)
    ),
    length(Vars, N),
    pairs_keys_values(Map, Args, Vars),
    Head =.. [Name|Vars],
    maplist(replace_constants_(Map), Body0, Body1),
    dedupe_(Body1, SBody),
    VS = vs(Head, SBody, [], [Example], [], []).

%!  vs_init_prior(+Example, +PriorLiterals, -VS) is det.
%
%   As vs_init/2, with the body literals of Example listed in PriorLiterals (ground,
%   as in Example: transfer:prior_literals/4 gives them, each as Kind-Literal with Kind
%   spatial or structural; a bare literal is structural) noted as the prior's
%   predictions, open (module comment): h_g starts empty, as without a prior, and no
%   literal is settled before the physics speaks. An open spatial literal is settled
%   by the first success that satisfies it; an open structural literal (a property of
%   the demonstrated tool) is never settled by a success, only tested like an unknown
%   literal, likelier necessary; a success that violates an open or settled literal
%   drops it (prior_dropped/2). A literal of PriorLiterals that Example lacks is
%   ignored.
%
%   ==
%   ?- vs_init_prior((tp(h1, c, t) :- hook(h1), behind(h1, c)),
%                    [spatial-behind(h1, c)], VS),
%      vs_bounds(VS, _, HG), vs_prior_open(VS, Open).
%   HG = tp(A, B, C), Open = [2].
%   ==
vs_init_prior(Example, PriorLits, VS) :-
    must_be(list, PriorLits),
    vs_init(Example, VS0),
    clause_head_body(Example, Head0, Body0),
    Head0 =.. [_|Args],
    VS0 = vs(Head, SBody, [], Pos, Neg, []),
    Head =.. [_|Vars],
    pairs_keys_values(Map, Args, Vars),
    maplist(prior_kind_, PriorLits, Kinded),
    include(in_example_(Body0), Kinded, Lits0),
    maplist(replace_kinded_(Map), Lits0, Lits1),
    include(in_sbody_(SBody), Lits1, Lits2),
    dedupe_kinded_(Lits2, Lits),
    maplist([K-L, prior(L, K)]>>true, Lits, Notes0),
    reverse(Notes0, Notes1),
    VS = vs(Head, SBody, [], Pos, Neg, [hg_learned([])|Notes1]).

prior_kind_(K-L, K-L) :-
    memberchk(K, [spatial, structural]),
    !.
prior_kind_(L, structural-L).

replace_kinded_(Map, K-L0, K-L) :-
    replace_constants_(Map, L0, L).

dedupe_kinded_([], []).
dedupe_kinded_([K-L|Ls], [K-L|Ds]) :-
    exclude([_-M]>>(M == L), Ls, Rest),
    dedupe_kinded_(Rest, Ds).

in_example_(Body, _-L) :-
    member_eq_(Body, L).

in_sbody_(SBody, _-L) :-
    member_eq_(SBody, L).

%!  vs_prior(+VS, -Kept:list, -Dropped:list) is det.
%
%   Kept are the prior's literals now in h_g, settled or confirmed (copies sharing the
%   head of vs_bounds/3's copy only by position: compare them as text or by variant),
%   Dropped the L-E pairs of literals a positive E contradicted, oldest first. Both []
%   for a version space without a prior.

vs_prior(VS, Kept, Dropped) :-
    copy_term(VS, vs(Head, _, GBody, _, _, Notes)),
    findall(L, ( member(prior(L, _), Notes), in_body_(Head, GBody, L) ), Kept0),
    reverse(Kept0, Kept),
    findall(L-E, member(prior_dropped(L, E), Notes), Dropped0),
    reverse(Dropped0, Dropped).

%!  vs_prior_events(+VS, -Events:list) is det.
%
%   Events are, oldest first, what the physics did to the prior's literals:
%   settled(L, E), confirmed(L, E) and dropped(L, E) (module comment), each L as the
%   first positive (the demonstration) instantiates it, as vs_init_prior/3 was given
%   it; [] without a prior.

vs_prior_events(VS, Events) :-
    copy_term(VS, vs(Head, _, _, [First|_], _, Notes)),
    clause_head_body(First, Head0, _),
    ignore(Head = Head0),
    findall(Ev, ( member(N, Notes), prior_event_(N, Ev) ), Evs0),
    reverse(Evs0, Events).

prior_event_(prior_settled(L, E), settled(L, E)).
prior_event_(prior_confirmed(L, E), confirmed(L, E)).
prior_event_(prior_dropped(L, E), dropped(L, E)).

%!  vs_prior_open(+VS, -Positions:list) is det.
%
%   Positions are the 1-based positions, in the literals of vs_space/4 (h_s's body
%   without in_range/3), of the prior's literals still open: neither in h_g nor
%   dropped. The informative strategy takes them as likelier necessary.

vs_prior_open(VS, Positions) :-
    copy_term(VS, vs(Head, SBody, GBody, _, _, Notes)),
    exclude(range_lit_, SBody, Lits),
    findall(I,
            ( member(prior(L, _), Notes),
              prior_open_(Head, GBody, Notes, L),
              nth1(I, Lits, L1),
              L1 == L
            ),
            Is),
    sort(Is, Positions).

prior_open_(Head, GBody, Notes, L) :-
    \+ in_body_(Head, GBody, L),
    \+ ( member(prior_dropped(D, _), Notes), D == L ).

%!  vs_prior_clause(+VS, -Clause) is semidet.
%
%   Clause is h_g's head with the prior's literals now in h_g (settled or confirmed)
%   as its body (Head alone when none is); fails for a version space without a prior
%   (vs_init/2).

vs_prior_clause(VS, Clause) :-
    copy_term(VS, vs(Head, _, GBody, _, _, Notes)),
    memberchk(prior(_, _), Notes),
    include(prior_kept_(Notes), GBody, Kept),
    clause_head_body(Clause, Head, Kept).

prior_kept_(Notes, L) :-
    member(prior(P, _), Notes),
    P == L,
    !.

replace_constants_(Map, T0, T) :-
    (   atom(T0),
        memberchk(T0-V, Map)
    ->  T = V
    ;   compound(T0)
    ->  compound_name_arguments(T0, Name, Args0),
        maplist(replace_constants_(Map), Args0, Args),
        compound_name_arguments(T, Name, Args)
    ;   T = T0
    ).

%!  vs_update(+VS0, +LabelledExample, -VS) is det.
%
%   VS is VS0 after the example LabelledExample, pos(E) or neg(E):
%
%     - pos(E): h_s becomes the clause_lgg/3 of h_s and E (without free
%       literals); literals of h_g that E violates are dropped (noted as
%       hg_weakened/2) and h_g is then specialised again against the stored
%       negatives, as below, so that it stays consistent when it can.
%     - neg(E): if h_g does not cover E, E is only stored. If h_s covers E,
%       E is noted as noisy_negative/1 and h_g is unchanged. Otherwise h_g is
%       specialised with a smallest set of h_s literals found greedily: at
%       each step the literal that excludes most of the stored (non-noisy)
%       negatives h_g still covers, preferring literals that E violates,
%       then body order; literals made redundant by later ones are removed
%       at the end.
%
%   Raises domain_error(labelled_example, X) for any other X.
%
%   ==
%   ?- vs_init((tp(h1, c, t) :- hook(h1), behind(h1, c)), VS0),
%      vs_update(VS0, neg((tp(h2, c, t) :- hook(h2), in_front(h2, c))), VS),
%      vs_bounds(VS, _, HG).
%   HG = (tp(T, C, X) :- behind(T, C)).
%   ==
vs_update(VS0, Labelled, VS) :-
    (   Labelled = pos(E)
    ->  clause_head_body(E, _, _),
        copy_term(VS0, VS1),
        update_pos_(VS1, E, VS)
    ;   Labelled = neg(E)
    ->  clause_head_body(E, _, _),
        copy_term(VS0, VS1),
        update_neg_(VS1, E, VS)
    ;   domain_error(labelled_example, Labelled)
    ).

update_pos_(vs(Head, SBody, GBody0, Pos0, Neg, Notes0), E, VS) :-
    memberchk(hg_learned(_), Notes0),
    !,
    update_pos_prior_(vs(Head, SBody, GBody0, Pos0, Neg, Notes0), E, VS).
update_pos_(vs(Head, SBody, GBody0, Pos0, Neg, Notes0), E, VS) :-
    clause_head_body(HS0, Head, SBody),
    clause_lgg(HS0, E, HS1),
    clause_head_body(HS1, Head1, SBody1),
    drop_free_literals_(Head1, SBody1, SBody2),
    Head = Head1,
    clause_head_body(HG0, Head, GBody0),
    (   clause_violations(HG0, E, Violated)
    ->  true
    ;   Violated = GBody0
    ),
    append(Pos0, [E], Pos),
    (   Violated == []
    ->  VS = vs(Head, SBody2, GBody0, Pos, Neg, Notes0)
    ;   exclude(member_eq_(Violated), GBody0, GBody1),
        drop_orphan_ranges_(Head, GBody1, GBody2),
        Notes1 = [hg_weakened(E, Violated)|Notes0],
        consistent_negatives_(Neg, Notes1, Negs),
        specialise_(Head, SBody2, GBody2, Negs, [], GBody, Left),
        note_noisy_(Left, Notes1, Notes),
        VS = vs(Head, SBody2, GBody, Pos, Neg, Notes)
    ).

%   A positive with a prior: the learned part of h_g changes exactly as h_g does
%   without a prior; the prior's literals E violates are dropped, the open spatial
%   ones it satisfies are settled; h_g is the learned part and the settled literals.
update_pos_prior_(vs(Head, SBody, GBody0, Pos0, Neg, Notes0), E, VS) :-
    select(hg_learned(LBody0), Notes0, NotesR),
    !,
    clause_head_body(HS0, Head, SBody),
    clause_lgg(HS0, E, HS1),
    clause_head_body(HS1, Head1, SBody1),
    drop_free_literals_(Head1, SBody1, SBody2),
    Head = Head1,
    append(Pos0, [E], Pos),
    violations_(Head, LBody0, E, LViol),
    prior_lits_(NotesR, PLits),
    violations_(Head, PLits, E, PViol),
    exclude(noted_(prior_dropped, NotesR), PViol, NewDrop),
    maplist(note_with_(prior_dropped, E), NewDrop, Dropped),
    append(Dropped, NotesR, Notes1),
    (   LViol == []
    ->  LBody = LBody0,
        Notes2 = Notes1
    ;   exclude(member_eq_(LViol), LBody0, LBody1),
        drop_orphan_ranges_(Head, LBody1, LBody2),
        Notes3 = [hg_weakened(E, LViol)|Notes1],
        consistent_negatives_(Neg, Notes3, Negs),
        specialise_(Head, SBody2, LBody2, Negs, [], LBody, Left),
        note_noisy_(Left, Notes3, Notes2)
    ),
    include(prior_spatial_open_(Head, GBody0, Notes2, PViol), PLits, ToSettle),
    maplist(note_with_(prior_settled, E), ToSettle, Settled),
    append(Settled, Notes2, Notes4),
    prior_hg_(Head, SBody2, LBody, E, Notes4, GBody, Notes),
    VS = vs(Head, SBody2, GBody, Pos, Neg, Notes).

%   h_g of a version space with a prior: the learned part LBody, then the settled
%   literals not dropped and not in it; notes the literals of the prior the learned
%   part now holds (confirmed by E) and the new learned part.
prior_hg_(Head, SBody, LBody, E, Notes0, GBody, [hg_learned(LBody)|Notes]) :-
    prior_lits_(Notes0, PLits),
    include(noted_(prior_settled, Notes0), PLits, Settled0),
    exclude(noted_(prior_dropped, Notes0), Settled0, Settled1),
    include(member_eq_(SBody), Settled1, Settled),
    exclude(in_body_(Head, LBody), Settled, Extra),
    append(LBody, Extra, GBody1),
    dedupe_(GBody1, GBody),
    include(in_body_(Head, LBody), PLits, InLearned),
    exclude(noted_(prior_confirmed, Notes0), InLearned, NewConf),
    maplist(note_with_(prior_confirmed, E), NewConf, Confirmed),
    append(Confirmed, Notes0, Notes).

%   The prior's literals (the very terms of the notes, sharing the head's variables),
%   in the order vs_init_prior/3 was given them. findall/3 would copy them.
prior_lits_(Notes, Lits) :-
    foldl(prior_lit_, Notes, [], Lits).

prior_lit_(N, Ls, [L|Ls]) :-
    N = prior(L, _),
    !.
prior_lit_(_, Ls, Ls).

%   noted_(+Name, +Notes, +L): Notes has Name(L, _) for this very L.
noted_(Name, Notes, L) :-
    member(N, Notes),
    compound(N),
    compound_name_arguments(N, Name, [L1, _]),
    L1 == L,
    !.

note_with_(Name, E, L, Note) :-
    Note =.. [Name, L, E].

prior_spatial_open_(Head, GBody, Notes, Violated, L) :-
    member(prior(L1, spatial), Notes),
    L1 == L,
    !,
    \+ member_eq_(Violated, L),
    prior_open_(Head, GBody, Notes, L).

violations_(Head, Lits, E, Viol) :-
    clause_head_body(C, Head, Lits),
    (   clause_violations(C, E, Viol)
    ->  true
    ;   Viol = Lits
    ).

update_neg_(vs(Head, SBody, GBody0, Pos, Neg0, Notes0), E, VS) :-
    select(hg_learned(LBody0), Notes0, NotesR),
    !,
    append(Neg0, [E], Neg),
    clause_head_body(HL0, Head, LBody0),
    clause_head_body(HS, Head, SBody),
    (   \+ clause_covers(HL0, E)
    ->  VS = vs(Head, SBody, GBody0, Pos, Neg, Notes0)
    ;   clause_violations(HS, E, Violated),
        Violated \== []
    ->  consistent_negatives_(Neg, NotesR, Negs),
        specialise_(Head, SBody, LBody0, Negs, Violated, LBody, Left),
        note_noisy_(Left, NotesR, Notes1),
        prior_hg_(Head, SBody, LBody, E, Notes1, GBody, Notes),
        VS = vs(Head, SBody, GBody, Pos, Neg, Notes)
    ;   VS = vs(Head, SBody, GBody0, Pos, Neg, [noisy_negative(E)|Notes0])
    ).
update_neg_(vs(Head, SBody, GBody0, Pos, Neg0, Notes0), E, VS) :-
    append(Neg0, [E], Neg),
    clause_head_body(HG0, Head, GBody0),
    clause_head_body(HS, Head, SBody),
    (   \+ clause_covers(HG0, E)
    ->  VS = vs(Head, SBody, GBody0, Pos, Neg, Notes0)
    ;   clause_violations(HS, E, Violated),
        Violated \== []
    ->  consistent_negatives_(Neg, Notes0, Negs),
        specialise_(Head, SBody, GBody0, Negs, Violated, GBody, Left),
        note_noisy_(Left, Notes0, Notes),
        VS = vs(Head, SBody, GBody, Pos, Neg, Notes)
    ;   VS = vs(Head, SBody, GBody0, Pos, Neg, [noisy_negative(E)|Notes0])
    ).

consistent_negatives_(Neg, Notes, Negs) :-
    exclude(noted_noisy_(Notes), Neg, Negs).

noted_noisy_(Notes, E) :-
    memberchk(noisy_negative(E), Notes).

note_noisy_([], Notes, Notes).
note_noisy_([E|Es], Notes0, Notes) :-
    (   memberchk(noisy_negative(E), Notes0)
    ->  Notes1 = Notes0
    ;   Notes1 = [noisy_negative(E)|Notes0]
    ),
    note_noisy_(Es, Notes1, Notes).

%   specialise_(+Head, +SBody, +GBody0, +Negs, +Prefer, -GBody, -Left):
%   greedy cover of the negatives h_g covers by units of h_s (a literal and
%   the range literals of its variables); Left are the negatives that even
%   all of h_s cannot exclude.
specialise_(Head, SBody, GBody0, Negs, Prefer, GBody, Left) :-
    clause_head_body(HG0, Head, GBody0),
    include(covers_(HG0), Negs, Covered),
    (   Covered == []
    ->  GBody = GBody0,
        Left = []
    ;   candidate_units_(Head, SBody, GBody0, Units),
        greedy_(Units, Head, GBody0, Covered, Prefer, [], Added, Left),
        minimise_(Added, Head, GBody0, Negs, Left, Kept),
        units_body_(Kept, GBody0, GBody)
    ).

covers_(Clause, E) :-
    clause_covers(Clause, E).

candidate_units_(Head, SBody, GBody, Units) :-
    partition(range_lit_, SBody, Ranges, Lits),
    exclude(in_body_(Head, GBody), Lits, Fresh),
    maplist(unit_(Ranges), Fresh, Units).

unit_(Ranges, L, unit(L, LRanges)) :-
    term_variables(L, Vs),
    include(range_on_(Vs), Ranges, LRanges).

range_on_(Vs, in_range(V, _, _)) :-
    member(W, Vs),
    W == V,
    !.

add_unit_(unit(L, Rs), G0, G) :-
    append(G0, [L|Rs], G1),
    dedupe_(G1, G).

units_body_(Units, GBody0, GBody) :-
    foldl(add_unit_, Units, GBody0, GBody).

greedy_(Units, Head, GBody0, Covered, Prefer, Added0, Added, Left) :-
    (   Covered == []
    ->  reverse(Added0, Added),
        Left = []
    ;   Units == []
    ->  reverse(Added0, Added),
        Left = Covered
    ;   reverse(Added0, InOrder),
        units_body_(InOrder, GBody0, GBody1),
        map_list_to_pairs(unit_score_(Head, GBody1, Covered, Prefer), Units, Scored),
        best_unit_(Scored, Best),
        selectchk(Best, Units, Rest),
        add_unit_(Best, GBody1, GBody2),
        clause_head_body(HG, Head, GBody2),
        include(covers_(HG), Covered, Covered1),
        greedy_(Rest, Head, GBody0, Covered1, Prefer, [Best|Added0], Added, Left)
    ).

%   Score s(Excluded, Preferred): more excluded negatives first, then
%   literals the new negative violates; ties keep the first in body order.
unit_score_(Head, GBody, Covered, Prefer, Unit, s(Excluded, Preferred)) :-
    add_unit_(Unit, GBody, GBody1),
    clause_head_body(HG, Head, GBody1),
    exclude(covers_(HG), Covered, Out),
    length(Out, Excluded),
    Unit = unit(L, _),
    (   member_eq_(Prefer, L)
    ->  Preferred = 1
    ;   Preferred = 0
    ).

best_unit_([S-U|Scored], Best) :-
    best_unit_(Scored, S, U, Best).

best_unit_([], _, Best, Best).
best_unit_([S-U|Scored], S0, U0, Best) :-
    (   S @> S0
    ->  best_unit_(Scored, S, U, Best)
    ;   best_unit_(Scored, S0, U0, Best)
    ).

%   Drop added units, last first, while the rest still excludes every
%   negative that the whole set excludes.
minimise_(Added, Head, GBody0, Negs, Left, Kept) :-
    subtract_eq_(Negs, Left, Targets),
    reverse(Added, Rev),
    foldl(try_drop_(Head, GBody0, Targets), Rev, Added, Kept).

try_drop_(Head, GBody0, Targets, Unit, Units0, Units) :-
    exclude(==(Unit), Units0, Without),
    units_body_(Without, GBody0, GBody),
    clause_head_body(HG, Head, GBody),
    (   \+ ( member(N, Targets), clause_covers(HG, N) )
    ->  Units = Without
    ;   Units = Units0
    ).

subtract_eq_([], _, []).
subtract_eq_([X|Xs], Ys, Zs) :-
    (   member_eq_(Ys, X)
    ->  Zs = Zs1
    ;   Zs = [X|Zs1]
    ),
    subtract_eq_(Xs, Ys, Zs1).

%   A literal with a variable that occurs once in the clause (and has no
%   range) says nothing an experiment could violate: drop it, repeatedly.
drop_free_literals_(Head, Body0, Body) :-
    partition(range_lit_, Body0, Ranges, Lits),
    (   select(L, Lits, Rest),
        has_free_var_(L, Head-Rest-Ranges)
    ->  exclude(==(L), Body0, Body1),
        drop_orphan_ranges_(Head, Body1, Body2),
        drop_free_literals_(Head, Body2, Body)
    ;   Body = Body0
    ).

has_free_var_(L, Others) :-
    term_variables(L, Vs),
    term_variables(Others, OVs),
    member(V, Vs),
    \+ ( member(W, OVs), W == V ),
    occurrences_of_var(V, L, 1),
    !.

drop_orphan_ranges_(Head, Body0, Body) :-
    exclude(range_lit_, Body0, Lits),
    term_variables(Head-Lits, Live),
    exclude(orphan_range_(Live), Body0, Body).

orphan_range_(Live, in_range(V, _, _)) :-
    \+ ( member(W, Live), W == V ).

range_lit_(in_range(_, _, _)).

member_eq_(List, X) :-
    member(Y, List),
    Y == X,
    !.

dedupe_([], []).
dedupe_([L|Ls], [L|Ds]) :-
    exclude(==(L), Ls, Rest),
    dedupe_(Rest, Ds).

%   L of h_s is already in h_g when some literal of h_g is a variant of it
%   once the shared head variables are fixed.
in_body_(Head, GBody, L) :-
    member(G, GBody),
    same_literal_(Head, L, G),
    !.

same_literal_(Head, L, G) :-
    \+ \+ ( numbervars(Head, 0, _, [functor_name('$head')]),
            L =@= G ).

%!  vs_bounds(+VS, -HS, -HG) is det.
%
%   HS and HG are copies of the boundary clauses h_s and h_g; they share
%   the same head term (and its variables).
%
%   ==
%   ?- vs_init((tp(h1, c, t) :- hook(h1)), VS), vs_bounds(VS, HS, HG).
%   HS = (tp(A, B, C) :- hook(A)), HG = tp(A, B, C).
%   ==
vs_bounds(VS, HS, HG) :-
    copy_term(VS, vs(Head, SBody, GBody, _, _, _)),
    clause_head_body(HS0, Head, SBody),
    clause_head_body(HG0, Head, GBody),
    HS = HS0,
    HG = HG0.

%!  vs_unknown(+VS, -Literals:list) is det.
%
%   Literals are the body literals of h_s (a copy) that are not in h_g,
%   compared as variants once the shared head is fixed, in h_s body order.
%   Range literals (`in_range/3`) are left out (see the module comment).
%
%   ==
%   ?- vs_init((tp(h1, c, t) :- hook(h1), behind(h1, c)), VS),
%      vs_unknown(VS, U).
%   U = [hook(A), behind(A, B)].
%   ==
vs_unknown(VS, Literals) :-
    copy_term(VS, vs(Head, SBody, GBody, _, _, _)),
    exclude(range_lit_, SBody, Lits),
    exclude(in_body_(Head, GBody), Lits, Literals).

%!  vs_examples(+VS, -Pos:list, -Neg:list) is det.
%
%   Pos and Neg are the positive and negative examples seen, in order
%   (Pos starts with the example of vs_init/2; Neg includes noisy ones).
%
%   ==
%   ?- vs_init((tp(h1, c, t) :- hook(h1)), VS), vs_examples(VS, P, N).
%   P = [(tp(h1, c, t) :- hook(h1))], N = [].
%   ==
vs_examples(vs(_, _, _, Pos, Neg, _), Pos, Neg).

%!  vs_converged(+VS) is semidet.
%
%   True when h_s and h_g agree: vs_unknown/2 gives [].
%
%   ==
%   ?- vs_init(tp(h1, c, t), VS), vs_converged(VS).
%   true.
%   ==
vs_converged(VS) :-
    vs_unknown(VS, []).

%!  vs_covers(+VS, +Bound, +Example) is semidet.
%
%   True when the boundary Bound (`hs` or `hg`) covers the example clause
%   Example (subsumption:clause_covers/2).
%
%   ==
%   ?- vs_init((tp(h1, c, t) :- hook(h1)), VS),
%      vs_covers(VS, hs, (tp(h2, c, t) :- hook(h2), red(h2))).
%   true.
%   ==
vs_covers(VS, Bound, Example) :-
    must_be(atom, Bound),
    vs_bounds(VS, HS, HG),
    (   Bound == hs
    ->  clause_covers(HS, Example)
    ;   Bound == hg
    ->  clause_covers(HG, Example)
    ;   domain_error(oneof([hs, hg]), Bound)
    ).

%!  vs_notes(+VS, -Notes:list) is det.
%
%   Notes lists, newest first, the inconsistencies met: hg_weakened(E,
%   Dropped) and noisy_negative(E) (see the module comment).
%
%   ==
%   ?- vs_init(tp(h1, c, t), VS), vs_notes(VS, N).
%   N = [].
%   ==
vs_notes(vs(_, _, _, _, _, Notes), Notes).


                 /*******************************
                 *   COUNTING THE HYPOTHESES    *
                 *******************************/

%!  vs_space(+VS, -HS, -Literals:list, -Constraints:list) is det.
%
%   The hypotheses of the version space as a hitting-set problem. HS is a copy of h_s
%   (the clause whose literals are numbered), Literals its body literals without the
%   in_range/3 tests, in body order; a hypothesis keeps a subset of them. Constraints
%   holds, for every recorded negative that some literal of h_s excludes (noisy
%   negatives are left out, as vs_update/3 leaves them out), the ordset of the
%   1-based positions in Literals of the literals it violates (a violated range counts
%   for the literal that binds its variable); a hypothesis is consistent with the
%   negative when it keeps at least one of them. Only the minimal sets are kept (a
%   superset of another constraint says nothing more).
%
%   h_g is one most general consistent hypothesis (vs_update/3 picks it greedily);
%   where a failure violated several literals of h_s, the others are consistent too,
%   and these constraints keep them all.
%
%   ==
%   ?- vs_init((tp(h1, c, t) :- hook(h1), behind(h1, c)), VS0),
%      vs_update(VS0, neg((tp(h2, c, t) :- stick(h2), in_front(h2, c))), VS),
%      vs_space(VS, _, Ls, Cs).
%   Ls = [hook(A), behind(A, B)], Cs = [[1, 2]].
%   ==
vs_space(VS, HS, Literals, Constraints) :-
    vs_bounds(VS, HS, _),
    clause_head_body(HS, _, Body),
    exclude(range_lit_, Body, Literals),
    vs_examples(VS, _, Negs),
    vs_notes(VS, Notes),
    consistent_negatives_(Negs, Notes, Consistent),
    findall(Set,
            ( member(N, Consistent),
              clause_violations(HS, N, Viol),
              vs_space_positions(Literals, Viol, Set),
              Set \== []
            ),
            Sets1),
    prior_sets_(VS, PriorSets),
    append(Sets1, PriorSets, Sets0),
    sort(Sets0, Sets),
    exclude(non_minimal_(Sets), Sets, Constraints).

%   The prior's settled literals still in h_g, each a constraint of its own position:
%   every hypothesis keeps it (relative to the prior, it is known necessary). Open
%   literals constrain nothing: they are predictions still to be tested.
prior_sets_(VS, Sets) :-
    copy_term(VS, vs(Head, SBody, GBody, _, _, Notes)),
    exclude(range_lit_, SBody, Lits),
    findall([I],
            ( member(prior_settled(L, _), Notes),
              \+ ( member(prior_dropped(D, _), Notes), D == L ),
              in_body_(Head, GBody, L),
              nth1(I, Lits, L1),
              L1 == L
            ),
            Sets).

%!  vs_space_positions(+Literals, +Violated, -Positions) is det.
%
%   Positions is the ordset of the 1-based positions in Literals (vs_space/4) of the
%   literals Violated names: the terms of the clause itself, as
%   subsumption:clause_violations/3 returns them (compared with ==); a violated
%   in_range/3 test counts for the literals that share its variable.

vs_space_positions(Literals, Viol, Set) :-
    findall(I,
            ( member(V, Viol),
              (   V = in_range(X, _, _)
              ->  nth1(I, Literals, L),
                  term_variables(L, LVs),
                  member(W, LVs), W == X
              ;   nth1(I, Literals, L),
                  L == V
              )
            ),
            Is),
    sort(Is, Set).

non_minimal_(Sets, S) :-
    member(T, Sets),
    T \== S,
    ord_subset(T, S),
    !.

%!  vs_space_count(+Literals, +Constraints, +Out, +Priors, -CountMass) is det.
%
%   CountMass is Count-Mass for the hypotheses over Literals (a list, only its length
%   counts) that keep none of the positions in Out and keep a literal of every set of
%   Constraints (positions as vs_space/4 gives them). Count is their number, an
%   integer; Mass their prior probability when each literal at position I is kept
%   (is necessary) with probability Priors[I], independently (numbers, rationals stay
%   exact); Priors = [] counts only (Mass is then 0). The count is exact: a literal in
%   no constraint doubles it, one in a constraint is split on (kept: the constraints
%   it hits are met; left out: it leaves them); the work grows with the literals the
%   constraints share, not with the number of literals.
%
%   ==
%   ?- vs_space_count([a, b, c], [[1, 2]], [], [], N-_).
%   N = 6.
%   ?- vs_space_count([a, b, c], [[1, 2]], [1], [], N-_).
%   N = 2.
%   ==
vs_space_count(Literals, Constraints, Out, Priors, Count-Mass) :-
    length(Literals, N),
    numlist_(N, All),
    sort(Out, OutSet),
    ord_subtract(All, OutSet, Free),
    maplist(ord_subtract_(OutSet), Constraints, Cs),
    (   Priors == []
    ->  count_(Free, Cs, Count),
        Mass = 0
    ;   out_mass_(OutSet, Priors, M0),
        count_mass_(Free, Cs, Priors, Count, M1),
        Mass is M0 * M1
    ).

numlist_(0, []) :- !.
numlist_(N, L) :- numlist(1, N, L).

ord_subtract_(Out, C0, C) :-
    ord_subtract(C0, Out, C).

out_mass_(Out, Priors, M) :-
    foldl(out_mass_step_(Priors), Out, 1, M).

out_mass_step_(Priors, I, M0, M) :-
    nth1(I, Priors, P),
    M is M0 * (1 - P).

%   count_(+Free, +Constraints, -Count): subsets of Free hitting every constraint.
count_(Free, Cs, Count) :-
    (   memberchk([], Cs)
    ->  Count = 0
    ;   Cs == []
    ->  length(Free, K),
        Count is 2^K
    ;   split_literal_(Cs, X),
        ord_del_element(Free, X, Free1),
        partition(ord_memberchk(X), Cs, Hit, Rest),
        maplist(ord_del_element_(X), Hit, Left),
        append(Left, Rest, CsOut),
        count_(Free1, Rest, In),
        count_(Free1, CsOut, OutN),
        Count is In + OutN
    ).

count_mass_(Free, Cs, Priors, Count, Mass) :-
    (   memberchk([], Cs)
    ->  Count = 0,
        Mass = 0
    ;   Cs == []
    ->  length(Free, K),
        Count is 2^K,
        Mass = 1                    % the free literals' choices sum to 1
    ;   split_literal_(Cs, X),
        ord_del_element(Free, X, Free1),
        partition(ord_memberchk(X), Cs, Hit, Rest),
        maplist(ord_del_element_(X), Hit, Left),
        append(Left, Rest, CsOut),
        count_mass_(Free1, Rest, Priors, In, MIn),
        count_mass_(Free1, CsOut, Priors, OutN, MOut),
        nth1(X, Priors, P),
        Count is In + OutN,
        Mass is P * MIn + (1 - P) * MOut
    ).

ord_del_element_(X, S0, S) :-
    ord_del_element(S0, X, S).

%   Split on the first literal of a smallest constraint.
split_literal_(Cs, X) :-
    map_list_to_pairs(length, Cs, Keyed),
    keysort(Keyed, [_-[X|_]|_]).

%!  vs_count(+VS, -Count:integer, -Exact:boolean) is det.
%
%   Count is the number of hypotheses of the version space: the conjunctions of
%   literals of h_s that exclude every recorded negative (vs_space/4), from h_s itself
%   to the most general ones (h_g among them). When no negative was recorded it is
%   2^U, U the literals of h_s; when every literal of h_g was made necessary by a
%   negative that violates it alone (one literal tested per trial), it is h_g plus
%   any subset of the unknown literals that excludes every negative. Exact is true
%   when at most 20 literals occur in the constraints (the count is then exact);
%   otherwise Count is an upper bound, the fewest hypotheses that meet any one
%   constraint alone, and Exact is false.
%
%   ==
%   ?- vs_init((tp(h1, c, t) :- hook(h1), behind(h1, c)), VS), vs_count(VS, N, E).
%   N = 4, E = true.
%   ==
vs_count(VS, Count, Exact) :-
    vs_space(VS, _, Literals, Constraints),
    ord_union(Constraints, Used),
    length(Used, NU),
    (   NU =< 20
    ->  vs_space_count(Literals, Constraints, [], [], Count-_),
        Exact = true
    ;   length(Literals, N),
        findall(B, ( member(C, Constraints),
                     length(C, K),
                     B is 2^N - 2^(N - K) ),
                Bounds),
        min_list(Bounds, Count),
        Exact = false
    ).
