# `cmake --build build --target docs`: regenerates the reference docs that are generated
# from the node registry and the diagnostic catalogue and checked in, docs/nodes.md,
# docs/diagnostics.md and docs/watergraph.schema.json (tests/cli/docs_test.cpp and
# tests/ecosystem/schema_test.cpp fail while one is stale).
# Run with -DWATERGRAPH=<binary> -DDOCS=<the docs folder>.
execute_process(COMMAND ${WATERGRAPH} nodes --markdown OUTPUT_FILE ${DOCS}/nodes.md.tmp RESULT_VARIABLE nodes_rc)
execute_process(COMMAND ${WATERGRAPH} codes --markdown OUTPUT_FILE ${DOCS}/diagnostics.md.tmp RESULT_VARIABLE codes_rc)
execute_process(COMMAND ${WATERGRAPH} schema -o ${DOCS}/watergraph.schema.json RESULT_VARIABLE schema_rc)
if(NOT nodes_rc EQUAL 0 OR NOT codes_rc EQUAL 0 OR NOT schema_rc EQUAL 0)
  file(REMOVE ${DOCS}/nodes.md.tmp ${DOCS}/diagnostics.md.tmp)
  message(FATAL_ERROR "watergraph failed to regenerate the docs (nodes: ${nodes_rc}, codes: ${codes_rc}, schema: ${schema_rc})")
endif()
# Written whole or not at all: a failed run leaves the checked-in file as it was.
file(RENAME ${DOCS}/nodes.md.tmp ${DOCS}/nodes.md)
file(RENAME ${DOCS}/diagnostics.md.tmp ${DOCS}/diagnostics.md)
message(STATUS "regenerated docs/nodes.md, docs/diagnostics.md and docs/watergraph.schema.json")
