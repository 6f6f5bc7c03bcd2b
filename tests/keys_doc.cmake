# Fails if docs/keys.md is not what the studies' schemas generate
# (GENERATOR: the wearscale_keys_doc program; DOC: the committed page).
execute_process(COMMAND ${GENERATOR} OUTPUT_VARIABLE generated RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "keys doc: ${GENERATOR} failed (${rc})")
endif()
file(READ ${DOC} committed)
if(NOT generated STREQUAL committed)
  message(FATAL_ERROR "docs/keys.md is not the page the schemas generate: regenerate it with "
                      "build/apps/wearscale_keys_doc > docs/keys.md")
endif()
