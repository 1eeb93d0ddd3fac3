# Loads a `bench-mbm --ompl-log` log into OMPL's own reader, Debian's /usr/bin/ompl_benchmark_statistics (package
# ompl-demos, installed by scripts/install-deps.sh), and checks the SQLite database it writes: one experiment, the
# expected planner entries, and per planner as many runs as the log has.
#   cmake -DSTATISTICS=/usr/bin/ompl_benchmark_statistics -DLOG=path -DDB=path -DPLANNERS=4 -DRUNS=1 -P ...
if(NOT STATISTICS OR NOT EXISTS "${STATISTICS}")
  message(FATAL_ERROR "ompl_benchmark_statistics not found: install Debian's ompl-demos (scripts/install-deps.sh)")
endif()
file(REMOVE "${DB}")
execute_process(COMMAND ${STATISTICS} "${LOG}" -d "${DB}" RESULT_VARIABLE code OUTPUT_VARIABLE out
                ERROR_VARIABLE err TIMEOUT 60)
if(NOT code EQUAL 0 OR NOT EXISTS "${DB}")
  message(FATAL_ERROR "ompl_benchmark_statistics ${LOG} failed (${code})\n${out}\n${err}")
endif()
set(query "import sqlite3, sys
db = sqlite3.connect(sys.argv[1])
print('experiments', db.execute('SELECT COUNT(*) FROM experiments').fetchone()[0])
print('version', db.execute('SELECT version FROM experiments').fetchone()[0])
for name, runs, solved in db.execute('SELECT p.name, COUNT(r.id), SUM(r.solved) FROM plannerConfigs p '
                                     'JOIN runs r ON r.plannerid = p.id GROUP BY p.id ORDER BY p.name'):
    print('planner', name, runs, solved)")
execute_process(COMMAND python3 -c "${query}" "${DB}" RESULT_VARIABLE code OUTPUT_VARIABLE summary
                ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "reading ${DB} failed:\n${err}")
endif()
message(STATUS "${DB}:\n${summary}")
if(NOT summary MATCHES "experiments 1\n")
  message(FATAL_ERROR "expected one experiment in ${DB}")
endif()
if(NOT summary MATCHES "version OMPL 1\\.5\\.2")
  message(FATAL_ERROR "expected the version 'OMPL 1.5.2' in ${DB}")
endif()
string(REGEX MATCHALL "planner geometric_[A-Za-z]+_[a-z_]+ ${RUNS} [0-9]+" planners "${summary}")
list(LENGTH planners found)
if(NOT found EQUAL PLANNERS)
  message(FATAL_ERROR "expected ${PLANNERS} planner entries with ${RUNS} run(s) each in ${DB}, found ${found}")
endif()
