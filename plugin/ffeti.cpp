// FreeFEM binding of ffeti: `load "ffeti"` registers the plugin's functions. The binding
// converts script data to core types (binding/convert.h), keeps problems behind integer
// handles between calls (binding/handles.h), reads named arguments and the solver options
// (binding/arguments.h) and turns core errors into FreeFEM errors. No numerics here:
// everything numerical lives in plugin/core.
#include "ff++.hpp"

#include "binding/functions.h"

static void Load_Init() {
  ffeti::binding::add_setup_functions();
  ffeti::binding::add_solve_functions();
  ffeti::binding::add_sensitivity_functions();
  ffeti::binding::add_contact_functions();
  ffeti::binding::add_utility_functions();
  ffeti::binding::add_mesh_functions();
}

LOADFUNC(Load_Init)
