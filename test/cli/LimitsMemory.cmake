# Issue 17 (bad input and first use), included by CMakeLists.txt. Memory: the option and the amount, never std::bad_alloc
ropras_cli_test(pomdp_run.particles_memory 2 "parameter particles = 100000000000 \\(particle filter\\) asks for 100000000000 x [0-9]+ bytes = .*TiB, more than the memory limit 1.0 GiB"
                ${lim} pomdp-run --episodes 1 --simulations 10 --param particles=100000000000)
ropras_cli_test(pomdp_run.planning_particles_memory 2 "planning particles \\(--planning-particles\\) 1000000000000 asks for"
                ${lim} pomdp-run --episodes 1 --simulations 10 --planning-particles 1000000000000)
ropras_cli_test(run.particles_memory 2 "parameter particles = 100000000000 \\(particle filter\\) asks for" ${lim} ${ld}
                --episodes 1 --param particles=100000000000)
ropras_cli_test(max_memory_zero 2 "memory limit must be at least 1 byte" --max-memory 0 pomdp-run --episodes 1)
ropras_cli_test(demo.samples_memory 2 "--samples 1000000000 \\(6 joints\\) asks for 1000000000 x [0-9]+ bytes = .*GiB, more than the memory limit 1.0 GiB"
                ${lim} demo --samples 1000000000)
ropras_cli_test(bench_collision.configs_memory 2 "--configs 1000000000000 per scene x 1 scenes, 6 joints asks for .*TiB, more than the memory limit"
                ${lim} ${bc_base} --configs 1000000000000)
ropras_cli_test(bench_collision.edges_memory 2 "--edges 100000000000 per scene" ${lim} ${bc_base} --configs 8 --edges
                100000000000)
