#!/usr/bin/env bash
# Regenerates the shipped sample-logs/ and the models/ learned from them.
#
# sample-logs/<scenario>/<scenario>-<seed>.log: 10 simulated runs per scenario, seeds 1..10, each seed with a
# different mix of the log variants a real YARP monitor log shows (docs/logs.md), so that learning on
# the samples also exercises the parser:
#   seed % 5 == 1: relative times, tab columns          seed % 5 == 2: epoch times, INFO raw-bottle lines
#   seed % 5 == 3: replies printed late (30%)            seed % 5 == 4: isAtLocation as YARP vocabs, spaces
#   seed % 5 == 0: epoch times, CRLF line endings
# The demo uses seeds from 9001 on, never these.
set -euo pipefail
cd "$(dirname "$0")/.."
JAR=target/predmon.jar
[ -f "$JAR" ] || mvn -q -B package -DskipTests
rm -rf sample-logs
for scenario in direct recharge depleted; do
  for seed in $(seq 1 10); do
    case $((seed % 5)) in
      1) flags=() ;;
      2) flags=(--epoch --raw-lines) ;;
      3) flags=(--late-replies 0.3) ;;
      4) flags=(--vocab --spaces) ;;
      0) flags=(--epoch --crlf) ;;
    esac
    java -jar "$JAR" simulate --scenario "$scenario" --seed "$seed" --runs 1 --out-dir "sample-logs/$scenario" \
      "${flags[@]}" > /dev/null
  done
done
java -jar "$JAR" learn --logs sample-logs --models models
