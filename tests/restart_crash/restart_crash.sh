#!/bin/bash
# The real crash: run the driver with checkpoints, kill -9 it once two
# checkpoints exist, resume it (on one rank and on two), and compare
# reactions.csv with an uninterrupted run.
#
#   restart_crash.sh <qsmpm executable> <directory of problem.prm>
#
# Same number of ranks: the resumed reactions must equal the uninterrupted
# ones to 1e-10 of the largest reaction, with the same steps (no row
# repeated). Written on one rank and resumed on two: to 1e-6 (the
# partitioned preconditioner gives other iterates within the Newton
# tolerance, 1e-8 here).
set -u
qsmpm=$1
source_dir=$2
work=$(pwd)/restart_crash.work
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1

make_prm() # name, output directory, checkpoint interval
{
  sed -e "s/OUTPUT/$2/" -e "s/CHECKPOINTS/$3/" "$source_dir/problem.prm" > "$1"
}
make_prm a.prm A 0
make_prm b.prm B 5
make_prm c.prm C 5

fail=0
check() # what, condition (0 = pass)
{
  if [ "$2" -eq 0 ]; then echo "$1: PASS"; else echo "$1: FAIL"; fail=1; fi
}

# Largest |difference| / largest |reaction| of two reactions.csv; prints
# "rows_a rows_b same_steps difference".
compare()
{
  awk -F, 'FNR == 1 { next }
    NR == FNR { n_a++; step_a[n_a] = $1; for (j = 2; j <= NF; ++j) { a[n_a, j] = $j; if (j > 2 && (v = ($j < 0 ? -$j : $j)) > big) big = v }; nf = NF; next }
    { n_b++; if ($1 != step_a[n_b] || $1 != n_b) same = 1
      for (j = 2; j <= NF; ++j) { d = a[n_b, j] - $j; if (d < 0) d = -d; if (j == 2) d /= 1; else d /= big; if (d > diff) diff = d } }
    END { printf "%d %d %d %.3g\n", n_a, n_b, (n_a == n_b ? same : 1), diff }' "$1" "$2"
}

start=$(date +%s.%N)
"$qsmpm" a.prm > a.log 2>&1 || { echo "uninterrupted run failed"; cat a.log; exit 1; }
end=$(date +%s.%N)
echo "uninterrupted run: $(echo "$end - $start" | bc) s"

# The run to be killed. It is a single process (no mpirun), so kill -9
# really ends all of it at once.
"$qsmpm" b.prm > b.log 2>&1 &
pid=$!
for i in $(seq 1 6000); do
  [ -d B/checkpoint-00010 ] && break
  kill -0 $pid 2> /dev/null || break
  sleep 0.01
done
sleep 0.1
kill -9 $pid 2> /dev/null
wait $pid 2> /dev/null
rows=$(($(wc -l < B/reactions.csv) - 1))
check "killed before the end of the run (60 steps)" $([ $rows -lt 60 ] && echo 0 || echo 1)
echo "killed after step $rows; checkpoints left: $(cd B && ls -d checkpoint* | tr '\n' ' ')"
cp -r B C

"$qsmpm" --resume b.prm > b-resume.log 2>&1
check "resume on one rank: exit code 0" $?
grep resumed b-resume.log
read n_a n_b same diff <<< "$(compare A/reactions.csv B/reactions.csv)"
echo "same ranks: $n_a rows uninterrupted, $n_b resumed, max difference / max reaction $diff"
check "same ranks: the steps of the uninterrupted run, none repeated" $same
check "same ranks: max difference <= 1e-10" "$(awk -v d=$diff 'BEGIN { print (d <= 1e-10 ? 0 : 1) }')"

mpirun -np 2 "$qsmpm" --resume c.prm > c-resume.log 2>&1
check "resume on two ranks: exit code 0" $?
read n_a n_b same diff <<< "$(compare A/reactions.csv C/reactions.csv)"
echo "1 -> 2 ranks: $n_a rows uninterrupted, $n_b resumed, max difference / max reaction $diff"
check "1 -> 2 ranks: the steps of the uninterrupted run, none repeated" $same
check "1 -> 2 ranks: max difference <= 1e-6" "$(awk -v d=$diff 'BEGIN { print (d <= 1e-6 ? 0 : 1) }')"

# A resume without a checkpoint: one line, non-zero exit.
"$qsmpm" --resume a.prm > a-resume.log 2>&1
status=$?
cat a-resume.log
check "resume without a checkpoint: non-zero exit and one line" \
  $([ $status -ne 0 ] && [ "$(wc -l < a-resume.log)" -eq 1 ] && echo 0 || echo 1)
exit $fail
