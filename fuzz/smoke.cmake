# One fuzz smoke run (cmake -P): the target FUZZER tries RUNS inputs, starting from the seed
# corpus SEEDS, with a fixed seed so that the run repeats. New inputs go to a fresh SCRATCH folder,
# never into the seeds; a finding fails the test and is left there as crash-*, leak-*, ...
file(REMOVE_RECURSE ${SCRATCH})
# Leaks inside Assimp's importers are not ours.
set(ENV{LSAN_OPTIONS} "suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan.supp:print_suppressions=0")
file(MAKE_DIRECTORY ${SCRATCH}/corpus)
execute_process(
  COMMAND ${FUZZER} -runs=${RUNS} -seed=1 -rss_limit_mb=2048 -timeout=10 -max_len=65536
          -artifact_prefix=${SCRATCH}/ ${SCRATCH}/corpus ${SEEDS}
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${FUZZER} found something (exit ${result}): see ${SCRATCH}")
endif()
