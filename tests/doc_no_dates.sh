#!/bin/bash
# The test doc_no_dates: the documentation is for users, not a lab diary.
#
#   doc_no_dates.sh <qsmpm source directory>
#
# In README.md, doc/*.md and examples/*/README.md, outside fenced code
# blocks:
#  1. no paragraph (nor list item, heading, table row or quote) starts with
#     a date: 2026-11-25, 2026-11, November 25, 25 November 2026,
#     11/25/2026, a weekday;
#  2. no ISO date (YYYY-MM-DD) anywhere: a figure says what it was measured
#     with (command, machine), not when; superseded figures go to an
#     appendix (see doc/benchmarks.md).
# Prints a FAIL line per offending line and a PASS line per clean page;
# exits non-zero if any check fails.
set -euo pipefail

source_dir=$(cd "${1:-$(dirname "$0")/..}" && pwd)
shopt -s nullglob
pages=("$source_dir"/README.md "$source_dir"/doc/*.md "$source_dir"/examples/*/README.md)
[ ${#pages[@]} -gt 0 ] || { echo "FAIL: no pages found in $source_dir"; exit 1; }

exec perl -e '
use strict;
use warnings;

my $months = "January|February|March|April|May|June|July|August|September|October|November|December|Jan|Feb|Mar|Apr|Jun|Jul|Aug|Sep|Sept|Oct|Nov|Dec";
my $date = qr{
    \d{4}-\d{1,2}(?:-\d{1,2})?\b
  | (?:$months)\.?\s+\d{1,2}\b
  | \d{1,2}\.?\s+(?:$months)\.?\s+\d{4}\b
  | \d{1,2}/\d{1,2}/\d{2,4}\b
  | (?:Mon|Tues|Wednes|Thurs|Fri|Satur|Sun)day\b
}x;

my $failures = 0;
for my $page (@ARGV) {
  open(my $in, "<", $page) or die "cannot read $page\n";
  my ($fence, $previous_blank, $n, $bad) = ("", 1, 0, 0);
  while (my $line = <$in>) {
    ++$n;
    if ($fence eq "" && $line =~ /^\s*(```+|~~~+)/) { $fence = substr($1, 0, 3); $previous_blank = 0; next; }
    if ($fence ne "") { $fence = "" if $line =~ /^\s*\Q$fence\E/; next; }
    my $blank = $line =~ /^\s*$/;
    (my $text = $line) =~ s/`[^`]*`//g;   # code spans
    my $block_start = $previous_blank
      || $line =~ /^\s*(?:[-*+]\s|\d+[.)]\s|#{1,6}\s|>|\|)/;
    if (!$blank && $block_start) {
      (my $start = $text) =~ s/^\s*(?:[-*+]\s+|\d+[.)]\s+|#{1,6}\s+|>\s*|\|\s*)*//;
      $start =~ s/^[\s*_(\[]+//;
      if ($start =~ /^(?:$date)/) {
        chomp(my $shown = $line);
        print "FAIL: $page:$n: a paragraph starts with a date: $shown\n";
        ++$bad;
      }
    }
    if ($text =~ /\b(\d{4}-\d{2}-\d{2})\b/) {
      chomp(my $shown = $line);
      print "FAIL: $page:$n: a date ($1): $shown\n";
      ++$bad;
    }
    $previous_blank = $blank;
  }
  close($in);
  if ($bad) { $failures += $bad; } else { print "PASS: $page: no dated paragraphs, no dates\n"; }
}
exit($failures ? 1 : 0);
' "${pages[@]}"
