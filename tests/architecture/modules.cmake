# The modules of libassess and the modules each may include (docs/architecture.md).
# A module may include its own headers and those of the modules listed here;
# anything else is an upward (or sideways) include and fails the test.
set(ASSESS_MODULES support hazard kinematic records dynamics assessment report campaign risk)
set(ASSESS_ALLOWED_support    "")
set(ASSESS_ALLOWED_hazard     "support")
set(ASSESS_ALLOWED_kinematic  "support;hazard")
set(ASSESS_ALLOWED_records    "support;hazard")
set(ASSESS_ALLOWED_dynamics   "support;hazard;kinematic;records")
set(ASSESS_ALLOWED_assessment "support;hazard;kinematic;records;dynamics")
set(ASSESS_ALLOWED_report     "support;hazard;kinematic;records;dynamics;assessment")
set(ASSESS_ALLOWED_campaign   "support;hazard;kinematic;records;dynamics;assessment;report")
set(ASSESS_ALLOWED_risk       "support;hazard;kinematic;records;dynamics;assessment;report;campaign")
