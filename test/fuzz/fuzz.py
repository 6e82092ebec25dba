#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Dictionary fuzzing: random single-key mutations of a tutorial's
dictionaries, each run for two CFD steps; no mutation may end in a
floating-point trap, a segmentation fault, a NaN in the log or a hang.

    fuzz.py --case labBed|pseudo2DBed --n N [--seed S] [--sample]
            [--timeout 120] [--jobs 1] WORKDIR

A mutation is one entry (`key value;` on one line) of one of the case's
dictionaries (FILES below), chosen at random (--seed), changed in one of
six ways: its numbers times 0, times -1, times 1e6, times 1e-6; its value
replaced by a word of the wrong type (fuzzValue); the entry removed. The
mutated case is meshed as its tutorial does and run for two CFD steps
(endTime set to 2 deltaT after the mutation; endTime, writeInterval and
the FoamFile headers are not mutated). Outcomes:
  ran       the run reached its end, no NaN in the log
  refused   a FOAM FATAL (IO) ERROR, or a case script's FATAL ERROR:
            the case stopped with a message (named: the message names
            the mutated key)
  trap      a floating-point exception (SIGFPE)
  segfault  a segmentation fault (SIGSEGV)
  nan       the run went on with a NaN in the log
  hang      no end within --timeout seconds
  (each run's memory is capped at 4 GB: a run that needs more fails as
  other, or as refused if the code names why first)
  other     any other failure (a message that is no FOAM error)
Writes WORKDIR/fuzz.tsv (one row per mutation: file, line, key, kind,
value, outcome, named, the log's first error line) and prints the count
of each outcome; exits 1 if any mutation ended in trap, segfault, nan,
hang or other. --sample: the fixed CI sample (seed 20261206)."""
import argparse
import os
import random
import re
import shutil
import signal
import subprocess
import sys

TOP = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                    '..', '..'))
FILES = {
    'labBed': ['system/caseSettings', 'system/fill.lattice',
               'system/gas.nitrogen', 'system/wallHeat.adiabatic',
               'constant/cloudProperties', 'constant/couplingProperties',
               'constant/materialProperties',
               'constant/thermophysicalProperties'],
    'pseudo2DBed': ['system/caseSettings', 'system/wallHeat.adiabatic',
                    'constant/cloudProperties',
                    'constant/couplingProperties',
                    'constant/materialProperties',
                    'constant/thermophysicalProperties'],
}
NOT_MUTATED = {'endTime', 'writeInterval', 'version', 'format', 'class',
               'object', 'location', 'arch', 'type', 'libs'}
KINDS = ['times0', 'negate', 'times1e6', 'times1e-6', 'wrongType', 'missing']
ENTRY = re.compile(r'^(\s*)([A-Za-z_][\w.:]*)(\s+)([^;{}]*?)\s*;(.*)$')
NUMBER = re.compile(r'(?<![\w.$])([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)(?![\w.])')
BAD = ('trap', 'segfault', 'nan', 'hang', 'other')


def candidates(case, src):
    """Every mutable entry: (file, line number, key, value)"""
    out = []
    for rel in FILES[case]:
        path = os.path.join(src, rel)
        if not os.path.exists(path):
            continue
        inHeader = False
        for i, line in enumerate(open(path).read().split('\n')):
            if line.strip().startswith('FoamFile'):
                inHeader = True
            if inHeader:
                if '}' in line:
                    inHeader = False
                continue
            if line.lstrip().startswith(('#', '//')):
                continue
            m = ENTRY.match(line)
            if m and m.group(2) not in NOT_MUTATED:
                out.append((rel, i, m.group(2), m.group(4)))
    return out


def mutate(value, kind):
    """(the value as the mutation makes it, or None to remove the entry;
    the mutation made): a numeric mutation of a value without a number
    becomes a wrong type (times 0: a removal)"""
    if kind == 'missing':
        return None, kind
    if kind == 'wrongType':
        return 'fuzzValue', kind
    factor = {'times0': 0.0, 'negate': -1.0, 'times1e6': 1e6,
              'times1e-6': 1e-6}[kind]
    if not NUMBER.search(value):
        return (None, 'missing') if kind == 'times0' else ('fuzzValue', 'wrongType')
    return (NUMBER.sub(lambda m: '%.10g' % (float(m.group(1))*factor), value),
            kind)


def applyMutation(case_dir, rel, lineNo, kind):
    """Mutate the entry: (the value written, the mutation made)"""
    path = os.path.join(case_dir, rel)
    lines = open(path).read().split('\n')
    m = ENTRY.match(lines[lineNo])
    new, made = mutate(m.group(4), kind)
    if new is None:
        lines[lineNo] = '// fuzz: removed ' + lines[lineNo].strip()
        shown = '(removed)'
    else:
        lines[lineNo] = '%s%s%s%s;%s' % (m.group(1), m.group(2), m.group(3),
                                         new, m.group(5))
        shown = new
    open(path, 'w').write('\n'.join(lines))
    return shown, made


def shortRun(case_dir, settings):
    """Two CFD steps: endTime 2 deltaT, after the mutation"""
    with open(os.path.join(case_dir, 'system', settings), 'a') as f:
        f.write('\nendTime     #eval{ 2*$deltaT };   // fuzz: two steps\n')


MEMORY_KB = 4000000    # each run's address space: a blow-up fails, not the machine


def run(cmd, cwd, log, timeout):
    """The command's return code, or 'timeout' (its whole process group
    killed: the shell and what it started)"""
    with open(os.path.join(cwd, log), 'w') as out:
        p = subprocess.Popen('ulimit -v %d; %s' % (MEMORY_KB, cmd), cwd=cwd,
                             stdout=out, stderr=subprocess.STDOUT, shell=True,
                             start_new_session=True)
        try:
            return p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
            return 'timeout'


def classify(case_dir, rc, key):
    text = ''
    for name in sorted(os.listdir(case_dir)):
        if name.startswith('log.'):
            text += open(os.path.join(case_dir, name), errors='replace').read()
    first = ''
    m = re.search(r'FOAM FATAL (?:IO )?ERROR[^\n]*\n(?:\s*\n)*([^\n]*)', text)
    if m:
        first = m.group(1).strip()[:160]
    if rc == 'timeout':
        return 'hang', False, first
    # (every log says the trap is enabled; its handler in a stack trace,
    # or the signal's exit code, is the trap itself)
    if (re.search(r'Floating point exception(?! trapping)', text)
            or 'sigFpe::sigHandler' in text or rc in (136, -8)):
        return 'trap', False, first
    if ('Segmentation fault' in text or 'sigSegv::sigHandler' in text
            or rc in (139, -11)):
        return 'segfault', False, first
    if rc == 0:
        if re.search(r'(?<![\w])-?nan(?![\w])', text, re.IGNORECASE):
            return 'nan', False, first
        return 'ran', False, first
    # OpenFOAM's fatal errors, and the case scripts' (makeBed: FATAL ERROR)
    fatal = re.search(r'FOAM FATAL|: FATAL ERROR:', text)
    if fatal:
        block = text[fatal.start():][:2000]
        if not first:
            first = block.split('\n')[0][:160]
        # named: the key as a word of the message (not inside another)
        named = re.search(r'(?<![\w.:])' + re.escape(key) + r'(?![\w:])',
                          block) is not None
        return 'refused', named, first
    tail = [l for l in text.strip().split('\n') if l.strip()][-1:] or ['']
    return 'other', False, tail[0][:160]


def prepare(case, src, work):
    """A copy of the tutorial, cleaned"""
    shutil.copytree(src, work)
    subprocess.run('./Allclean', cwd=work, shell=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    for d in ('run', 'regimes'):
        shutil.rmtree(os.path.join(work, d), ignore_errors=True)


def runCase(case, work, timeout):
    """Mesh and run the mutated case as its tutorial does: return code"""
    if case == 'labBed':
        shortRun(work, 'caseSettings')
        rc = run('blockMesh', work, 'log.blockMesh', timeout)
        if rc != 0:
            return rc
        return run('sinterFoam', work, 'log.sinterFoam', timeout)
    shortRun(work, 'caseSettings')
    rc = run('./setupCase run adiabatic', work, 'log.setupCase', timeout)
    runDir = os.path.join(work, 'run')
    if rc != 0:
        # setupCase's own logs (blockMesh, topoSet, makeBed) say why
        if os.path.isdir(runDir):
            for name in os.listdir(runDir):
                if name.startswith('log.'):
                    shutil.copy(os.path.join(runDir, name),
                                os.path.join(work, name + '.setup'))
        return rc
    rc = run('sinterFoam', runDir, 'log.sinterFoam', timeout)
    shutil.copy(os.path.join(runDir, 'log.sinterFoam'),
                os.path.join(work, 'log.sinterFoam'))
    return rc


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--case', required=True, choices=sorted(FILES))
    ap.add_argument('--n', type=int, default=20)
    ap.add_argument('--seed', type=int, default=1)
    ap.add_argument('--sample', action='store_true')
    ap.add_argument('--timeout', type=float, default=120)
    ap.add_argument('--keep', action='store_true', help='keep every case')
    ap.add_argument('workdir')
    a = ap.parse_args()
    seed = 20261206 if a.sample else a.seed
    src = os.path.join(TOP, 'tutorials', 'sinterFoam', a.case)
    cands = candidates(a.case, src)
    rng = random.Random(seed)
    picks = [(rng.choice(cands), rng.choice(KINDS)) for _ in range(a.n)]
    os.makedirs(a.workdir, exist_ok=True)
    rows, counts = [], {}
    for k, ((rel, lineNo, key, value), kind) in enumerate(picks):
        work = os.path.join(a.workdir, '%s-%03d' % (a.case, k))
        shutil.rmtree(work, ignore_errors=True)
        prepare(a.case, src, work)
        shown, kind = applyMutation(work, rel, lineNo, kind)
        rc = runCase(a.case, work, a.timeout)
        outcome, named, first = classify(work, rc, key)
        counts[outcome] = counts.get(outcome, 0) + 1
        rows.append((rel, lineNo + 1, key, kind, value, shown, outcome,
                     'named' if named else '-', first))
        print('%3d %-34s %-24s %-10s %-26s -> %-8s %s' % (
            k, rel, key, kind, shown[:26], outcome,
            ('named ' if named else '') + first[:70]), flush=True)
        if outcome not in BAD and not a.keep:
            shutil.rmtree(work, ignore_errors=True)
    with open(os.path.join(a.workdir, 'fuzz.tsv'), 'w') as f:
        f.write('# file\tline\tkey\tmutation\tvalue\tmutated\toutcome\tnamed'
                '\tfirst error line\n')
        for r in rows:
            f.write('\t'.join(str(x) for x in r) + '\n')
    print('%s, seed %d, %d mutations: %s' % (
        a.case, seed, len(rows),
        ', '.join('%s %d' % (o, counts[o]) for o in sorted(counts))))
    return 1 if any(counts.get(o) for o in BAD) else 0


if __name__ == '__main__':
    sys.exit(main())
