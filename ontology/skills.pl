/*  The robot's own innate skills, the same in every case.

    Plain Prolog data loaded into the shared module kb by knowledge:load_ontology/1.

    innate_skill(?Case, ?Name, ?Model): Model is the STRIPS model of the innate skill
    Name in Case, an action_model(Name, Params, Pre, Add, Del) term (prolog/action_model.pl
    describes it).  A clause whose Case is a variable holds for every case; a case's
    own skills are in its file under ontology/cases/, and it lists the skills it uses,
    in plan order, with case_skills/2.  The robot's state literals (gripper_empty,
    holding/1, on_table/1) are observed by the engine (experiment:observed_state/3).
*/

innate_skill(_AnyCase, pick_up,
             action_model(pick_up, [T-tool],
                          [gripper_empty, on_table(T)],
                          [holding(T)],
                          [gripper_empty, on_table(T)])).
