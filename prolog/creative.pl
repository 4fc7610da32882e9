%   CREATIVE-py: load the whole learning engine, for the REPL and for the tests.
%
%       swipl prolog/creative.pl
%
%   Every module of prolog/ is loaded with use_module/1, so its exports are visible at
%   the top level. The ontology (background knowledge: the .pl files of ontology/) is
%   loaded at the end with knowledge:load_default_ontology/0.

:- multifile user:file_search_path/2.
:- dynamic user:file_search_path/2.
:- prolog_load_context(directory, Dir),
   asserta(user:file_search_path(creative, Dir)),
   file_directory_name(Dir, Root),
   directory_file_path(Root, ontology, Onto),
   asserta(user:file_search_path(ontology, Onto)),
   asserta(user:file_search_path(creative_root, Root)).

:- use_module(library(lists)).
:- use_module(library(apply)).

%   Load every module file beside this one (one module per file, see docs/architecture.md §3).
:- prolog_load_context(directory, Dir),
   directory_files(Dir, Entries),
   msort(Entries, Sorted),
   forall(( member(E, Sorted),
            file_name_extension(Base, pl, E),
            Base \== creative
          ),
          ( directory_file_path(Dir, E, Path),
            use_module(Path)
          )).

%   The default background knowledge (ontology/*.pl), so that the REPL and the bridge
%   start with the tool hierarchies, ranges, spatial definitions and replacement
%   operators loaded.
:- knowledge:load_default_ontology.
