#!/usr/bin/python3
"""How the rows of batch 3 (haselREC_NGA-West2/) entered metadata.csv (issue 30), kept as provenance.

Run once, from this folder: /usr/bin/python3 import_records3.py
It reads
  records-3-catalogue.csv                       (the source table of batch 3, same columns as records-2's)
  haselREC_NGA-West2/_SearchResults.csv         (PEER NGA-West2 search report, 2019-10-30, 86 RSNs)
  haselREC_NGA-West2/Flatfile-NGA-West2-Reduced.csv (haselREC's reduced flatfile: RotD50 PGA)
and rewrites metadata.csv:
  * adds the columns `pulse` and `pulse_period_s` if missing: the pulse classification of the PEER search
    report (column "Tp-Pulse Period (sec)": a number = pulse-like with that pulse period, "-" = not
    pulse-like; NGA-West2 classification, Shahi & Baker 2014) for every row whose RSN the report covers,
    batches 1 and 2 included; empty = not classified by any source we have;
  * appends one row per component of batch 3 (unless its file is already listed): positive direction from
    the azimuth, lowest usable frequency from the search report where it gives one, and the two kinds of
    doubtful record marked excluded with the reason (records-3 README, "Quirks"): component "NA" (unknown
    orientation) and the three RSNs whose file PGAs disagree with the flatfile's RotD50 PGA by more than
    25 % (RotD50 / geometric mean of the two file PGAs outside 0.8-1.25).
metadata.csv is hand-kept after this; catalogue.json and spectra.bin are generated from it by
`assess records build`.
"""
import csv, math, os, re

HERE = os.path.dirname(os.path.abspath(__file__))
META = os.path.join(HERE, 'metadata.csv')
SRC = os.path.join(HERE, 'records-3-catalogue.csv')
REPORT = os.path.join(HERE, 'haselREC_NGA-West2', '_SearchResults.csv')
FLAT = os.path.join(HERE, 'haselREC_NGA-West2', 'Flatfile-NGA-West2-Reduced.csv')
REPORT_NAME = 'PEER NGA-West2 search report 2019-10-30 (haselREC_NGA-West2/_SearchResults.csv)'


def search_report():
    """RSN -> (Tp or None, lowest usable Hz)."""
    lines = open(REPORT, encoding='latin-1').read().splitlines()
    start = [k for k, l in enumerate(lines) if l.startswith('Result ID')][0]
    out = {}
    for l in lines[start + 1:]:
        if not l.strip() or not l[0].isdigit():
            break
        r = [c.strip() for c in next(csv.reader([l], skipinitialspace=True))]
        tp = None if r[5] == '-' else float(r[5])
        out[int(r[2])] = (tp, float(r[17]))
    return out


def rotd50_ratio(rows):
    """RSN -> RotD50 PGA (flatfile) / geometric mean of the two file PGAs."""
    rot = {int(x['record_sequence_number_NGA']): float(x['rotD50_pga']) for x in csv.DictReader(open(FLAT))}
    by = {}
    for r in rows:
        by.setdefault(rsn_of(r['file'], r['notes']), []).append(float(r['PGA_g']))
    return {k: rot[k] / math.sqrt(v[0] * v[1]) for k, v in by.items() if len(v) == 2 and k in rot}


def rsn_of(file, notes):
    m = re.search(r'RSN\s?(\d+)', os.path.basename(file)) or re.search(r'NGA-West2 RSN (\d+)', notes)
    return int(m.group(1)) if m else None


def direction(comp):
    if comp.upper() == 'NA':
        return 'unknown (the header gives component NA)'
    az = int(comp) % 360
    names = {0: 'N', 90: 'E', 180: 'S', 270: 'W'}
    return names.get(az, 'azimuth %d deg (clockwise from N)' % az)


def main():
    report = search_report()
    with open(META, newline='') as f:
        reader = csv.DictReader(f)
        header = list(reader.fieldnames)
        rows = list(reader)
    for col in ('pulse', 'pulse_period_s'):
        if col not in header:
            header.insert(header.index('lowest_usable_hz') + 1 + (col == 'pulse_period_s'), col)
    for r in rows:
        rsn = rsn_of(r['file'], r['notes'])
        r.setdefault('pulse', '')
        r.setdefault('pulse_period_s', '')
        if rsn in report and not r['pulse']:
            tp = report[rsn][0]
            r['pulse'] = 'pulse-like' if tp is not None else 'non-pulse'
            r['pulse_period_s'] = '%g' % tp if tp is not None else ''
            r['notes'] += '; pulse classification (RSN %d) from the %s' % (rsn, REPORT_NAME)
    listed = {r['file'] for r in rows}
    src = list(csv.DictReader(open(SRC)))
    ratio = rotd50_ratio(src)
    for s in src:
        file = s['file']
        if file in listed:
            continue
        rsn = rsn_of(file, s['notes'])
        tp, luf = report.get(rsn, (None, None))
        m = re.search(r'lowest usable freq ([0-9.]+) Hz', s['notes'])
        excluded = ''
        if s['component'].upper() == 'NA':
            excluded = ('orientation unknown: the AT2 header gives component NA (records-3 README, Quirks); '
                        'its partner component is kept')
        elif rsn in ratio and not 0.8 <= ratio[rsn] <= 1.25:
            excluded = ('doubtful: the file PGAs disagree with the NGA-West2 flatfile (RotD50 PGA / geometric '
                        'mean of the two file PGAs = %.2f, outside 0.8-1.25; records-3 README, Quirks)' % ratio[rsn])
        rows.append({
            'file': file, 'event': s['event'], 'date': s['date'], 'Mw': s['Mw'], 'mechanism': s['mechanism'],
            'station': s['station'], 'station_code': s['station_code'], 'component': s['component'],
            'positive_direction': direction(s['component']), 'distance_km': s['distance_km'],
            'distance_kind': s['distance_kind'], 'vs30_m_s': s['vs30'], 'site_class_stated': s['site_class'],
            'country': s['country'], 'lowest_usable_hz': m.group(1) if m else ('%g' % luf if luf else ''),
            'pulse': ('pulse-like' if tp is not None else 'non-pulse') if rsn in report else '',
            'pulse_period_s': '%g' % tp if tp is not None else '',
            'plain_dt_s': '', 'plain_unit': '', 'excluded_reason': excluded, 'source': s['source'],
            'terms': s['licence'],
            'notes': s['notes'] + ('; pulse classification from the ' + REPORT_NAME if rsn in report else '')
                     + '; batch 3 (records-3, issue 30)',
        })
    with open(META, 'w', newline='') as f:
        w = csv.DictWriter(f, fieldnames=header, lineterminator='\n')
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, '') for k in header})


if __name__ == '__main__':
    main()
