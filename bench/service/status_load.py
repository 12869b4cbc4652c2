#!/usr/bin/python3
"""Fixed-rate status reads against `slamsweep serve` for the load test (bench/service/load_test.sh).

Usage: status_load.py URL RATE SECONDS SWEEP_IDS_FILE OUT_JSON

Sends RATE requests per second for SECONDS (open loop: each request has its planned start time, and its
latency counts from that time, so a slow server cannot hide its queueing by slowing the client down),
cycling over GET /api/sweeps, /api/sweeps/ID, /api/sweeps/ID/runs and / for the submitted sweeps.
Writes the latency percentiles, the status codes and the achieved rate to OUT_JSON.
"""
import http.client
import json
import sys
import threading
import time
import urllib.parse

THREADS = 8


def main():
    url, rate, seconds, ids_file, out_file = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4], sys.argv[5]
    ids = [line.strip() for line in open(ids_file) if line.strip()]
    paths = ["/api/sweeps", "/"]
    for sweep_id in ids:
        paths += [f"/api/sweeps/{sweep_id}", f"/api/sweeps/{sweep_id}/runs"]
    parsed = urllib.parse.urlparse(url)
    total = int(rate * seconds)
    start = time.monotonic() + 0.2
    latencies, codes, errors = [], {}, []
    lock = threading.Lock()

    def worker(index):
        connection = http.client.HTTPConnection(parsed.hostname, parsed.port, timeout=30)
        for n in range(index, total, THREADS):
            planned = start + n / rate
            delay = planned - time.monotonic()
            if delay > 0:
                time.sleep(delay)
            try:
                connection.request("GET", paths[n % len(paths)])
                response = connection.getresponse()
                response.read()
                status = response.status
            except (OSError, http.client.HTTPException) as error:
                connection.close()
                connection = http.client.HTTPConnection(parsed.hostname, parsed.port, timeout=30)
                status = "error"
                with lock:
                    errors.append(str(error))
            elapsed = time.monotonic() - planned
            with lock:
                latencies.append(elapsed)
                codes[str(status)] = codes.get(str(status), 0) + 1

    threads = [threading.Thread(target=worker, args=(i,)) for i in range(THREADS)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    wall = time.monotonic() - start
    latencies.sort()

    def percentile(p):
        return latencies[min(len(latencies) - 1, int(p / 100.0 * len(latencies)))] * 1000.0

    result = {
        "requests": len(latencies),
        "planned": total,
        "achieved_rate_per_s": len(latencies) / wall,
        "status_codes": codes,
        "errors": errors[:5],
        "p50_ms": percentile(50),
        "p90_ms": percentile(90),
        "p99_ms": percentile(99),
        "max_ms": latencies[-1] * 1000.0,
    }
    json.dump(result, open(out_file, "w"), indent=2)
    print(json.dumps(result))


if __name__ == "__main__":
    main()
