#pragma once
// How idle OpenMP threads wait. libgomp spins a waiting thread for about 300,000 turns
// before it sleeps: on a core that another program also wants, the spinning thread takes
// that core's time from the thread it waits for, and a run of many short parallel regions
// goes ten or twenty times slower than on one thread. mpmx's parallel regions are long
// (a batch of MD boxes, a step of a large system), so sleeping at once costs nothing
// measurable there. libgomp reads its settings when it is loaded, before main(), so a
// process whose environment says nothing starts itself again with OMP_WAIT_POLICY=passive.
namespace mpmx {

// Called first thing in main(): returns only if the waiting policy is already set (by the
// user: OMP_WAIT_POLICY or GOMP_SPINCOUNT, left as they are), or if the restart failed
// (then the run goes on with libgomp's default).
void wait_passively(char** argv);

}  // namespace mpmx
