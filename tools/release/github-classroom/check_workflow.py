#!/usr/bin/env python3
"""Checks the GitHub Classroom workflow's structure (Debian has no actionlint):
what GitHub Actions needs to run it and what the reporter needs to read the
result. Prints each fault and exits 1, or exits 0.
Usage: check_workflow.py WORKFLOW.yml RELEASE_OR_CHECKOUT_FILES_DIR
(the second: where the files the workflow runs are, to check they exist)."""
import os
import re
import sys

import yaml

WORKFLOW_KEYS = {"name", "on", "permissions", "jobs", "env", "defaults", "concurrency", "run-name"}
EVENTS = {"push", "pull_request", "workflow_dispatch", "repository_dispatch", "schedule"}
JOB_KEYS = {"name", "runs-on", "if", "timeout-minutes", "steps", "permissions", "env", "defaults",
            "needs", "outputs", "strategy", "container", "services", "continue-on-error", "environment",
            "concurrency"}
STEP_KEYS = {"name", "id", "if", "uses", "run", "with", "env", "shell", "working-directory",
             "continue-on-error", "timeout-minutes"}
# What the reporter needs to write the check run's "Points X/Y" (it updates a check run).
PERMISSIONS = {"checks": "write", "actions": "read", "contents": "read"}
REPORTER = "classroom-resources/autograding-grading-reporter"
ID = re.compile(r"^[A-Za-z_][A-Za-z0-9_-]*$")
USES = re.compile(r"^[A-Za-z0-9_.-]+/[A-Za-z0-9_.-]+(/[A-Za-z0-9_./-]+)?@[A-Za-z0-9_.-]+$")
EXPRESSION = re.compile(r"\$\{\{(.*?)\}\}")
STEP_OUTPUT = re.compile(r"^\s*steps\.([A-Za-z_][A-Za-z0-9_-]*)\.outputs\.([A-Za-z_][A-Za-z0-9_-]*)\s*$")


def expressions(value, where, faults):
    """Every ${{ }} in a string is closed; returns their contents."""
    if not isinstance(value, str):
        return []
    if value.count("${{") != len(EXPRESSION.findall(value)):
        faults.append(f"{where}: an expression ${{{{ without its }}}}")
    return EXPRESSION.findall(value)


def check(doc, files_dir):
    faults = []
    if not isinstance(doc, dict):
        return ["not a mapping at the top"]
    # YAML 1.1 reads an unquoted `on` as true: GitHub reads it as the key "on".
    if True in doc:
        doc["on"] = doc.pop(True)
    for key in set(doc) - WORKFLOW_KEYS:
        faults.append(f"unknown top-level key {key!r}")
    events = doc.get("on")
    names = set(events) if isinstance(events, (list, dict)) else {events}
    if "push" not in names:
        faults.append("'on' does not include push: a student's push would run nothing")
    for e in names - EVENTS:
        faults.append(f"unknown event {e!r}")
    perms = doc.get("permissions")
    for k, v in PERMISSIONS.items():
        if not isinstance(perms, dict) or perms.get(k) != v:
            faults.append(f"permissions: {k} must be {v} (the reporter updates the check run)")
    jobs = doc.get("jobs")
    if not isinstance(jobs, dict) or len(jobs) != 1:
        return faults + ["jobs: expected exactly one job"]
    (job_id, job), = jobs.items()
    if not ID.match(str(job_id)):
        faults.append(f"job id {job_id!r} is not a valid id")
    if not isinstance(job, dict):
        return faults + [f"job {job_id}: not a mapping"]
    for key in set(job) - JOB_KEYS:
        faults.append(f"job {job_id}: unknown key {key!r}")
    if not job.get("runs-on"):
        faults.append(f"job {job_id}: no runs-on")
    if not isinstance(job.get("timeout-minutes"), int):
        faults.append(f"job {job_id}: timeout-minutes must be a whole number")
    expressions(job.get("if"), f"job {job_id}: if", faults)
    steps = job.get("steps")
    if not isinstance(steps, list) or not steps:
        return faults + [f"job {job_id}: no steps"]
    ids, outputs_used, reporters = [], [], []
    for i, step in enumerate(steps):
        where = f"step {i + 1}"
        if not isinstance(step, dict):
            faults.append(f"{where}: not a mapping")
            continue
        where = f"step {i + 1} ({step.get('name', '')})"
        for key in set(step) - STEP_KEYS:
            faults.append(f"{where}: unknown key {key!r}")
        if ("uses" in step) == ("run" in step):
            faults.append(f"{where}: needs exactly one of uses and run")
        if "uses" in step and not USES.match(str(step["uses"])):
            faults.append(f"{where}: uses {step['uses']!r} is not owner/repo@ref")
        if "with" in step and "uses" not in step:
            faults.append(f"{where}: with without uses")
        if "run" in step:
            run = step["run"]
            if not isinstance(run, str) or "\n" in run.strip():
                faults.append(f"{where}: run must be one line (the release's test runs each run: line)")
            else:
                script = re.match(r"^bash (\S+)$", run.strip())
                if script and not os.path.isfile(os.path.join(files_dir, script.group(1))):
                    faults.append(f"{where}: runs {script.group(1)}, which is not in {files_dir}")
        if "id" in step:
            if not ID.match(str(step["id"])):
                faults.append(f"{where}: id {step['id']!r} is not a valid id")
            if step["id"] in ids:
                faults.append(f"{where}: id {step['id']!r} used twice")
            ids.append(step["id"])
        for section in ("env", "with"):
            for key, value in (step.get(section) or {}).items():
                for expr in expressions(value, f"{where}: {section}.{key}", faults):
                    m = STEP_OUTPUT.match(expr)
                    if m:
                        if m.group(1) not in ids:
                            faults.append(f"{where}: {section}.{key} reads step {m.group(1)!r}, "
                                          "which is not an earlier step")
                        outputs_used.append((m.group(1), m.group(2), section, key))
        if str(step.get("uses", "")).startswith(REPORTER + "@"):
            reporters.append((where, step))
    if len(reporters) != 1:
        return faults + [f"expected one step using {REPORTER}, found {len(reporters)}"]
    where, reporter = reporters[0]
    runners = [r.strip() for r in str((reporter.get("with") or {}).get("runners", "")).split(",") if r.strip()]
    if not runners:
        faults.append(f"{where}: with.runners names no runner")
    env = reporter.get("env") or {}
    for runner in runners:
        # The reporter reads each runner's result from <RUNNER>_RESULTS, base64.
        name = runner.upper() + "_RESULTS"
        if name not in env:
            faults.append(f"{where}: runner {runner!r} has no env {name}")
            continue
        exprs = [STEP_OUTPUT.match(e) for e in expressions(env[name], f"{where}: env.{name}", faults)]
        if len(exprs) != 1 or not exprs[0] or exprs[0].group(1) != runner or exprs[0].group(2) != "result":
            faults.append(f"{where}: env {name} must be ${{{{ steps.{runner}.outputs.result }}}}")
    return faults


def main():
    path, files_dir = sys.argv[1], sys.argv[2]
    try:
        with open(path, encoding="utf-8") as f:
            doc = yaml.safe_load(f)
    except yaml.YAMLError as e:
        print(f"{path}: not YAML: {e}")
        return 1
    faults = check(doc, files_dir)
    for fault in faults:
        print(f"{path}: {fault}")
    if not faults:
        print(f"{path}: a valid GitHub Classroom workflow")
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main())
