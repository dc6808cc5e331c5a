# assess.run and assess.kinematic return what `assess run/kinematic CASE --json`
# print: the same dict, key for key and number for number (the library builds
# both documents; risk/run_report.hpp).
import json
import os

import assess
from conftest import CHURCH, cli, cli_json


def test_version_is_the_cli_version():
    out, _ = cli("--version")
    assert out.strip() == "assess " + assess.__version__


def test_church_equals_cli_json():
    py = assess.run(CHURCH)
    assert py == cli_json("run", CHURCH, "--json")
    # the verdicts a relazione signs: every approach of the comparison
    assert py["comparison"] and py["checks"] and py["safety_indices"]


def test_church_from_dict_has_the_same_verdicts():
    with open(CHURCH, encoding="utf-8") as f:
        doc = json.load(f)
    by_path = assess.run(CHURCH)
    by_dict = assess.run(doc)
    assert by_dict["checks"] == by_path["checks"]
    assert by_dict["comparison"] == by_path["comparison"]
    assert by_dict["safety_indices"] == by_path["safety_indices"]


def test_kinematic_equals_cli_json():
    case = os.path.join("mechanisms", "two_storey_facade.json")
    assert assess.kinematic(case) == cli_json("kinematic", case, "--json")


def test_kinematic_with_ties_equals_cli_json():
    case = os.path.join("mechanisms", "church-facade-ties.json")
    assert assess.kinematic(case) == cli_json("kinematic", case, "--json")


def test_building_equals_cli_json():
    case = os.path.join("tests", "cli", "building", "chiesa_piccola.json")
    assert assess.run(case) == cli_json("run", case, "--json")
