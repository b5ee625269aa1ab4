#!/usr/bin/env python3
"""A model extended with one view (pcl_tensor_model --keep-poses) against a full run of the same views.

For each set: a model of every view but one (with --cache), the model extended with that view
(--keep-poses the first model's .conf), then a full run of every view from the same cache. Prints, per
set, what each registered, the worst pose error of each against the ground truth, the added view's error
and the three wall times.

    python3 bench/scale/extend_benchmark.py --bin build/apps --real dragon_stand:0,5,14 --real bunny:0,4,9
    python3 bench/scale/extend_benchmark.py --bin build/apps --ring 12 --rings DIR   # DIR/NAME_r12 from pcl_tensor_views
"""
import argparse
import json
import os
import random
import shutil

import scale_benchmark as sb

MESHES = ['beast', 'cheburashka', 'cow', 'fandisk', 'homer', 'rocker-arm', 'spot', 'teapot', 'example', 'bun_zipper',
          'dragon_vrip']


def names_of(report):
    return [os.path.basename(v['file']) for v in report['views']]


def extend(bin_dir, views, held, truth, centre, out, extra):
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    cache = ['--cache', os.path.join(out, 'cache')] + extra
    old = views[:held] + views[held + 1:]
    runs = [sb.run_model(bin_dir, old, out, cache, 'before')]
    runs.append(sb.run_model(bin_dir, old + [views[held]], out, cache + ['--keep-poses', runs[0][3]], 'extended'))
    runs.append(sb.run_model(bin_dir, old + [views[held]], out, cache, 'full'))
    added = os.path.basename(views[held])
    record = {'added': added, 'wall_s': [round(r[0], 2) for r in runs]}
    for label, (_, _, report, conf) in zip(['before', 'extended', 'full'], runs):
        worst_r, worst_t, within = sb.score(report, truth, conf, centre)
        errors = sb.pose_errors(truth, sb.load_conf(conf), names_of(report)[report['reference']], centre, report['resolution'])
        record[label] = {'registered': report['registered'], 'models': report['components'], 'within': within,
                         'worst': [round(worst_r, 3), round(worst_t, 2)],
                         'added': [round(x, 3) for x in errors[added]] if added in errors else None}
    return record


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--bin', default='build/apps')
    ap.add_argument('--real', action='append', default=[], help='SET:I,J,... a Stanford set (shuffled) and the views to add')
    ap.add_argument('--ring', type=int, help='rendered rings of this many views, shuffled, the last one added')
    ap.add_argument('--rings', help='folder of the rings (NAME_rN, each with views.conf)')
    ap.add_argument('--out', default='bench_results/extend')
    args = ap.parse_args()
    for spec in args.real:
        name, held = spec.split(':')
        _, views, truth, centre = sb.real(name, args.out)
        for h in [int(x) for x in held.split(',')]:
            record = extend(args.bin, views, h, truth, centre, os.path.join(args.out, '%s_%d' % (name, h)), [])
            print(json.dumps(dict(set=name, **record)), flush=True)
    if args.ring:
        for name in MESHES:
            folder = os.path.join(args.rings, '%s_r%d' % (name, args.ring))
            truth = sb.load_conf(os.path.join(folder, 'views.conf'))
            views = sorted(os.path.join(folder, f) for f in truth)
            random.Random(5).shuffle(views)
            record = extend(args.bin, views, len(views) - 1, truth, sb.look_at_centre(truth),
                            os.path.join(args.out, '%s_r%d' % (name, args.ring)), ['--viewpoint', '0,0,0'])
            print(json.dumps(dict(set=name, **record)), flush=True)


if __name__ == '__main__':
    main()
