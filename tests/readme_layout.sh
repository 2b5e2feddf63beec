#!/bin/bash
# The test readme_layout: README.md must describe the library as it is.
#
#   readme_layout.sh <qsmpm source directory>
#
# Checks, one PASS or FAIL line each:
#  1. every header under include/qsmpm/ (also version.h.in, installed as
#     version.h) is named in the section "## Layout" of README.md, by its
#     file name without .h (`utilities.h`, `parameter_file`) or by its main
#     class, the CamelCase of that name (quasi_static_residual.h ->
#     QuasiStaticResidual);
#  2. every constitutive model the library registers
#     (QSMPM_REGISTER_CONSTITUTIVE_MODEL(Class, "name", ...) in source/) and
#     every name a model of include/qsmpm/materials/ returns from name() is
#     named in that section in backticks (`von Mises`);
#  3. README.md opens with what a newcomer needs: a picture and the two
#     commands (build and run the main example; run the test suite) within
#     its first 40 lines.
# Exits non-zero if any check fails.
set -euo pipefail

source_dir=$(cd "${1:-$(dirname "$0")/..}" && pwd)
readme=$source_dir/README.md
[ -f "$readme" ] || { echo "FAIL: no README.md in $source_dir"; exit 1; }

exec perl -e '
use strict;
use warnings;
use File::Find;

my ($source_dir, $readme) = @ARGV;
my $failures = 0;
sub pass { print "PASS: $_[0]\n"; }
sub fail { print "FAIL: $_[0]\n"; ++$failures; }

open(my $fh, "<", $readme) or die "cannot read $readme\n";
my @lines = <$fh>;
close($fh);

# The section "## Layout", up to the next heading of the same level.
my ($in, $layout) = (0, "");
for (@lines) {
  if (/^## /) { $in = /^## Layout\s*$/ ? 1 : 0; next; }
  $layout .= $_ if $in;
}
if ($layout eq "") {
  fail("README.md has no section \"## Layout\"");
  exit 1;
}

# 1. Headers.
my @headers;
find({ wanted => sub { push @headers, $File::Find::name if /\.h(\.in)?$/ },
       no_chdir => 1 }, "$source_dir/include/qsmpm");
fail("no headers found under $source_dir/include/qsmpm") unless @headers;
for my $header (sort @headers) {
  (my $relative = $header) =~ s{^\Q$source_dir\E/}{};
  (my $base = $header) =~ s{.*/}{};
  $base =~ s/\.in$//;
  $base =~ s/\.h$//;
  my $class = join("", map { ucfirst } split(/_/, $base));
  if ($layout =~ /(?<![A-Za-z0-9_])\Q$class\E(?![A-Za-z0-9_])/) {
    pass("$relative: class $class named in the Layout section");
  } elsif ($layout =~ /(?<![A-Za-z0-9_])\Q$base\E(?![A-Za-z0-9_])/) {
    pass("$relative: $base named in the Layout section");
  } else {
    fail("$relative: neither $class nor $base is named in the Layout section of README.md");
  }
}

# 2. Registered models and the names models return.
my %models;
my @sources;
find({ wanted => sub { push @sources, $File::Find::name if /\.(cc|h)$/ },
       no_chdir => 1 }, "$source_dir/source", "$source_dir/include/qsmpm");
for my $file (@sources) {
  open(my $in, "<", $file) or die "cannot read $file\n";
  local $/;
  my $text = <$in>;
  close($in);
  while ($text =~ /QSMPM_REGISTER_CONSTITUTIVE_MODEL\s*\(\s*(\w+)\s*,\s*"([^"]+)"/g) {
    $models{$2} = "registered as $1";
  }
  while ($text =~ /\bname\s*\(\s*\)\s*const\s*override\s*\{\s*return\s+"([^"]+)"\s*;/g) {
    $models{$1} //= "returned by name() in the header";
  }
}
fail("no registered models found under $source_dir/source") unless %models;
for my $model (sort keys %models) {
  if ($layout =~ /`\Q$model\E`/) {
    pass("model `$model` ($models{$model}) named in the Layout section");
  } else {
    fail("model `$model` ($models{$model}) is not named (in backticks) in the Layout section of README.md");
  }
}

# 3. The opening: a picture and the two commands within 40 lines.
my $head = join("", @lines[0 .. ($#lines < 39 ? $#lines : 39)]);
($head =~ /^!\[[^\]]*\]\([^)]+\)/m)
  ? pass("README.md shows a picture within its first 40 lines")
  : fail("README.md shows no picture within its first 40 lines");
($head =~ /^apt-get update .*cmake --build build .*\.\/compact_tension b15\.prm/m)
  ? pass("README.md gives the command that builds and runs the main example within its first 40 lines")
  : fail("the command that builds and runs the main example is not within the first 40 lines of README.md");
($head =~ /^cd build && .*ctest --output-on-failure/m)
  ? pass("README.md gives the command that runs the test suite within its first 40 lines")
  : fail("the command that runs the test suite is not within the first 40 lines of README.md");

exit($failures ? 1 : 0);
' "$source_dir" "$readme"
