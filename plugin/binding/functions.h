// The plugin's functions, registered with FreeFEM by group (plugin/ffeti.cpp).
#pragma once

namespace ffeti::binding {

void add_setup_functions();        ///< fetiSetup, fetiSetLoads, fetiFree (setup.cpp)
void add_solve_functions();        ///< fetiSolve, fetiInfo, fetiHistory, fetiReport (solve.cpp)
void add_sensitivity_functions();  ///< fetiSensitivity, fetiAdjoint, fetiAdjointGradient (sensitivity.cpp)
void add_contact_functions();      ///< fetiContact, fetiContactPressure, fetiContactStart, fetiConstraints (contact.cpp)
void add_utility_functions();      ///< fetiIndices, ranks, sums, clocks (utilities.cpp)
void add_mesh_functions();         ///< fetiConnectParts, fetiSplitMesh3 (meshes.cpp)

}  // namespace ffeti::binding
