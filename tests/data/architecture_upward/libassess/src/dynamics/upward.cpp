// Fixture for tests/architecture: dynamics may not include report.
#include "assess/dynamics/rocking_model.hpp"
#include "assess/report/plot.hpp"
