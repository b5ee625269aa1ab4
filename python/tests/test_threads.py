"""Registrations from several Python threads: the same results as one after the other, with the GIL
released while the C++ works."""
import threading

import numpy as np

import pcl_tensor

ORIGIN = (0.0, 0.0, 0.0)


def run(views, pair):
    return pcl_tensor.register(views.path(pair[0]), views.path(pair[1]), ORIGIN, ORIGIN)


def test_two_threads_give_the_results_of_two_sequential_runs(ring_views):
    pairs = [(0, 1), (5, 6)]
    sequential = [run(ring_views, p) for p in pairs]
    concurrent = [None, None]

    def worker(k):
        concurrent[k] = run(ring_views, pairs[k])

    threads = [threading.Thread(target=worker, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for a, b in zip(sequential, concurrent):
        assert a.registered and b.registered
        assert np.array_equal(a.transform, b.transform)
        assert a.report["hypotheses_tried"] == b.report["hypotheses_tried"]


def test_the_interpreter_runs_while_a_registration_works(ring_views):
    done = threading.Event()
    result = []

    def worker():
        result.append(run(ring_views, (0, 1)))
        done.set()

    thread = threading.Thread(target=worker)
    thread.start()
    ticks = 0
    while not done.is_set():
        ticks += 1
        done.wait(0.001)
    thread.join()
    assert result[0].registered
    # With the GIL held for the whole registration (tens of milliseconds), the loop could not run.
    assert ticks >= 5
