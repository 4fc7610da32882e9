:- begin_tests(knowledge).

:- use_module('../../prolog/knowledge').

%   write_temp_ontology_(+Text, -Path): a temporary .pl file holding Text.
write_temp_ontology_(Text, Path) :-
    tmp_file_stream(text, Path0, S0),
    close(S0),
    delete_file(Path0),
    file_name_extension(Path0, pl, Path),
    setup_call_cleanup(open(Path, write, S), write(S, Text), close(S)).

test(default_ontology_loads, [setup(load_default_ontology)]) :-
    kb_loaded_files(Files),
    length(Files, N),
    assertion(N >= 6),
    assertion(kb_module_holds(kind_hook_like, subclass_of(hook, hook_like))),
    assertion(shared_holds(qualitative_range(handle_length, medium, 0.25, 0.45))).

%   Each case file is its own module, seeing its kind's and the shared one; each kind
%   file is its own; the other files are shared (kb).
test(each_case_and_kind_has_its_module, [setup(load_default_ontology)]) :-
    assertion(kb_case_module(hook, case_hook)),
    assertion(kb_case_module(wedge, case_wedge)),
    assertion(kb_kind_module(hook_like, kind_hook_like)),
    kb_module_scope(case_hook, HookScope),
    assertion(HookScope == [case_hook, kind_hook_like, apparatus_tube, kb]),
    kb_module_scope(case_wedge, WedgeScope),
    assertion(WedgeScope == [case_wedge, kind_block, kb]),
    assertion(\+ kb_module_defines(kb, spatial_definition/4)),
    assertion(\+ kb_module_defines(kb, subclass_of/2)),
    assertion(kb_module_defines(kb, qualitative_range/5)).

%   The files of ontology/ first, then each subfolder's, in name order.
test(default_ontology_reads_subfolders_in_order, [setup(load_default_ontology)]) :-
    kb_loaded_files(Files),
    maplist([F, Rel]>>( file_base_name(F, Base),
                        file_directory_name(F, D),
                        file_base_name(D, Dir),
                        atomic_list_concat([Dir, Base], /, Rel) ),
            Files, Rels),
    once(nth1(IHook, Rels, 'cases/hook.pl')),
    once(nth1(IWedge, Rels, 'cases/wedge.pl')),
    once(nth1(IBlock, Rels, 'kinds/block.pl')),
    once(nth1(IRanges, Rels, 'ontology/ranges.pl')),
    assertion(IRanges < IHook),
    assertion(IHook < IWedge),
    assertion(IWedge < IBlock).

test(reload_replaces_clauses, [setup(load_default_ontology)]) :-
    aggregate_all(count, shared_clause(any_length(_), _), N0),
    load_default_ontology,
    aggregate_all(count, shared_clause(any_length(_), _), N),
    assertion(N0 == 3),
    assertion(N == 3).

test(syntax_error_names_file_and_line,
     [ setup(write_temp_ontology_("ok(a).\n\nbad(X) :- ok(X.\n", F)),
       cleanup(delete_file(F)),
       error(syntax_error(_), file(F, 3, _, _)) ]) :-
    load_ontology(F).

test(unknown_predicate_names_predicate_file_and_line,
     [ setup(write_temp_ontology_("ok(a).\n\nuses(X) :-\n    ok(X),\n    frobnicate(X).\n", F)),
       cleanup(delete_file(F)),
       error(existence_error(procedure, frobnicate/1), file(F, 3, _, _)) ]) :-
    load_ontology(F).

test(failed_load_asserts_nothing,
     [ setup(write_temp_ontology_("marker_fact_kn(a).\nuses(X) :- nowhere_kn(X).\n", F)),
       cleanup(delete_file(F)) ]) :-
    catch(load_ontology(F), error(existence_error(procedure, nowhere_kn/1), _), true),
    \+ current_predicate(kb:marker_fact_kn/1).

test(directive_is_rejected,
     [ setup(write_temp_ontology_(":- dynamic foo/1.\n", F)),
       cleanup(delete_file(F)),
       error(domain_error(ontology_clause, _), file(F, 1, _, _)) ]) :-
    load_ontology(F).

test(missing_file, [error(existence_error(source_sink, '/nonexistent/onto.pl'))]) :-
    load_ontology('/nonexistent/onto.pl').

test(calls_may_refer_to_primitive_predicates,
     [ setup(write_temp_ontology_("primitive_predicate(weight_kg_kn/2).\nheavy_kn(X) :- weight_kg_kn(X, W), W > 1.\n", F)),
       cleanup(( kb_reset_all, delete_file(F), load_default_ontology )) ]) :-
    load_ontology(F),
    \+ shared_holds(heavy_kn(rock)),
    kb_assert_facts([weight_kg_kn(rock, 2.0)]),
    shared_holds(heavy_kn(rock)).

test(world_facts_and_reset,
     [ setup(load_default_ontology), cleanup(kb_reset) ]) :-
    kb_assert_facts([object_kind(h9, hook), handle_length_m(h9, 0.5)]),
    kb_module_holds(kind_hook_like, handle_length(h9, V)),
    assertion(V == long),
    kb_retract_facts(handle_length_m(h9, _)),
    \+ kb_module_holds(kind_hook_like, handle_length(h9, _)),
    kb_module_holds(kind_hook_like, hook(h9)),
    kb_reset,
    \+ kb_module_holds(kind_hook_like, hook(h9)),
    kb_module_holds(kind_hook_like, subclass_of(stick, hook_like)).

test(assert_rejects_non_ground, [error(instantiation_error)]) :-
    kb_assert_facts([pose(_, 0, 0, 0, 0)]).

test(assert_rejects_clauses, [error(type_error(fact, _))]) :-
    kb_assert_facts([(a :- b)]).

test(prove_from_fact_list, [setup(load_default_ontology)]) :-
    findall(V, kb_module_prove(case_hook, handle_length(h, V),
                               [object_kind(h, stick), handle_length_m(h, 0.2)]), Vs),
    assertion(Vs == [short]),
    \+ kb_module_prove(case_hook, handle_length(h, _), [object_kind(h, stick)]),
    %   a kind's rule is not the shared module's
    catch(shared_prove(handle_length(h, _), [object_kind(h, stick)]), E, true),
    assertion(E = error(existence_error(procedure, kb:handle_length/2), _)).

%   A case's body may call only its own, its kind's and the shared predicates: a call
%   to another case's helper is an unknown predicate.
test(case_cannot_call_another_case_s_helper,
     [ setup(write_temp_ontology_("case(peek_kn).\nlooks(X) :- tip_in_tube(X).\n", F)),
       cleanup(delete_file(F)),
       error(existence_error(procedure, tip_in_tube/1), file(F, 2, _, _)) ]) :-
    load_default_ontology,
    load_ontology(F).

%   An apparatus file (apparatus/1) is its own module, seen by the cases that name it
%   (case_apparatus/2), after their kind's: the tube is written once, the hook and the
%   paddle case both use it, the rake does not see it.
test(apparatus_is_its_own_module_seen_by_its_cases, [setup(load_default_ontology)]) :-
    assertion(kb_apparatus_module(tube, apparatus_tube)),
    assertion(kb_module_scope(apparatus_tube, [apparatus_tube, kb])),
    kb_module_scope(case_paddle_tube, PaddleScope),
    assertion(PaddleScope == [case_paddle_tube, kind_paddle, apparatus_tube, kb]),
    kb_module_scope(case_rake, RakeScope),
    assertion(RakeScope == [case_rake, kind_hook_like, kb]),
    assertion(kb_module_defines(apparatus_tube, in_tube/2)),
    forall(member(M, [case_hook, case_paddle_tube, kb]),
           assertion(\+ kb_module_defines(M, in_tube/2))),
    State = [tube_mouth(tube1, 0.6, 0.0, 0.0), tube_length_m(tube1, 0.3),
             tube_inner_m(tube1, 0.08, 0.07), pose(cube1, 0.8, 0.0, 0.0, 0.0)],
    assertion(kb_module_prove(case_hook, in_tube(cube1, tube1), State)),
    assertion(kb_module_prove(case_paddle_tube, in_tube(cube1, tube1), State)),
    catch(kb_module_prove(case_rake, in_tube(cube1, tube1), State), E, true),
    assertion(E = error(existence_error(procedure, case_rake:in_tube/2), _)).

%   A case that does not name the apparatus cannot call its helpers; one that does can.
test(case_calls_apparatus_only_when_it_names_it,
     [ setup(( write_temp_ontology_("case(peek_ap).\nlooks(X) :- tube_dx_max(c, X, _).\n", F),
               write_temp_ontology_("case(uses_ap).\ncase_apparatus(uses_ap, tube).\nlooks(X) :- tube_dx_max(c, X, _).\n", G) )),
       cleanup(( delete_file(F), delete_file(G), kb_reset_all, load_default_ontology )) ]) :-
    load_default_ontology,
    catch(load_ontology(F), E, true),
    assertion(E = error(existence_error(procedure, tube_dx_max/3), file(F, 2, _, _))),
    load_ontology(G),
    kb_module_scope(case_uses_ap, Scope),
    assertion(Scope == [case_uses_ap, apparatus_tube, kb]),
    assertion(kb_module_prove(case_uses_ap, looks(0.005),
                              [tube_mouth(tube1, 0.6, 0.0, 0.0), tube_length_m(tube1, 0.3),
                               pose(c, 0.9, 0.0, 0.0, 0.0)])).

%   A kind's root class need not be named like its kind (file): a case naming the class
%   sees the kind whose hierarchy holds it.
test(case_sees_the_kind_of_its_class_whatever_the_kind_s_name,
     [ setup(( write_temp_ontology_("kind(spoons_kn).\nsubclass_of(spoon_kn, tool).\nbowl_kn(T) :- spoon_kn(T).\nspoon_kn(t1).\n", K),
               write_temp_ontology_("case(c_kn).\ncase_tool_class(c_kn, spoon_kn).\nuses_kn(T) :- bowl_kn(T).\n", C) )),
       cleanup(( delete_file(K), delete_file(C), kb_reset_all, load_default_ontology )) ]) :-
    load_default_ontology,
    load_ontology_files([K, C]),
    kb_module_scope(case_c_kn, Scope),
    assertion(Scope == [case_c_kn, kind_spoons_kn, kb]),
    assertion(kb_module_holds(case_c_kn, uses_kn(t1))).

%   A case naming a class no kind has is refused at load, in one line that names the
%   file and what to rename it to.
test(case_tool_class_of_no_kind_names_the_root_classes,
     [ setup(write_temp_ontology_("case(c_kn2).\n\ncase_tool_class(c_kn2, hook_likes).\n", F)),
       cleanup(( delete_file(F), kb_reset_all, load_default_ontology )) ]) :-
    load_default_ontology,
    catch(load_ontology(F), E, true),
    assertion(E = error(existence_error(tool_class, hook_likes, root_classes(_)),
                        file(F, 3, -1, 0))),
    E = error(Formal, _),
    message_to_codes_(error(Formal, _), Text),
    %   the root classes are those of the kinds loaded, whichever they are
    findall(Part,
            ( kb_kind_module(_, M),
              knowledge:file_module_(File, M),
              kb_module_holds(M, subclass_of(Root, Parent)),
              \+ kb_module_holds(M, subclass_of(Parent, _)),
              file_base_name(File, Base),
              format(string(Part), "~w of kinds/~w", [Root, Base]) ),
            Parts),
    assertion(memberchk("hook_like of kinds/hook_like.pl", Parts)),
    assertion(memberchk("block of kinds/block.pl", Parts)),
    atomic_list_concat(Parts, ', ', Roots),
    format(string(Expected), "case_tool_class/2 names the tool class hook_likes, which no kind of ontology/kinds/ has: rename it to a kind's root class (~w), or add subclass_of(hook_likes, tool) to its kind's file", [Roots]),
    assertion(Text == Expected),
    assertion(\+ kb_case_module(c_kn2, _)).

message_to_codes_(error(Formal, _), Text) :-
    phrase(prolog:error_message(Formal), Lines),
    with_output_to(string(Text0), print_message_lines(current_output, '', Lines)),
    split_string(Text0, "", "\n", [Text]).

test(two_roles_in_one_file_rejected,
     [ setup(write_temp_ontology_("case(a_kn).\ncase(b_kn).\n", F)),
       cleanup(delete_file(F)),
       error(domain_error(one_role_per_file, _), file(F, 1, _, _)) ]) :-
    load_ontology(F).

test(reset_all_then_reload, [cleanup(load_default_ontology)]) :-
    load_default_ontology,
    kb_reset_all,
    kb_loaded_files(Fs),
    assertion(Fs == []),
    \+ current_predicate(kb:subclass_of/2).

:- end_tests(knowledge).
