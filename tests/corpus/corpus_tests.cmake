# The real-scene corpus (samples/corpus, issue 29): made from Debian's assimp-testmodels by
# samples/corpus/make_corpus.py into build/corpus (fixture corpus.make), each scene baked with the
# defaults and checked (tests/corpus/bake_scene.py: validator, atlas, energy balance, clipping),
# then all seen in three.js, stock and with the plugin (tests/corpus/three.test.mjs); the house's
# daylight run (tests/corpus/daylight_scene.py). `ctest -L corpus`.
set(RADBAKE_CORPUS_DIR ${CMAKE_BINARY_DIR}/corpus)
set(RADBAKE_CORPUS_BAKES ${CMAKE_BINARY_DIR}/corpus_bakes)
add_test(NAME corpus.make COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/samples/corpus/make_corpus.py ${RADBAKE_CORPUS_DIR})
set_tests_properties(corpus.make PROPERTIES FIXTURES_SETUP corpus_scenes LABELS corpus TIMEOUT 300)
add_test(NAME corpus.daylight.fzk_haus
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/corpus/daylight_scene.py $<TARGET_FILE:radbake>
          ${RADBAKE_CORPUS_DIR} fzk_haus ${RADBAKE_CORPUS_BAKES} 2)
set_tests_properties(corpus.daylight.fzk_haus PROPERTIES FIXTURES_REQUIRED corpus_scenes LABELS corpus TIMEOUT 600)
