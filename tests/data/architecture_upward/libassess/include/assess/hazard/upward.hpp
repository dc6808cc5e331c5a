// Fixture for tests/architecture: hazard may not include assessment.
#pragma once
#include <assess/assessment/case_file.hpp>
