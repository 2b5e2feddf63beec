#!/bin/bash
# The tests doc_links and installed_doc_links: every relative link of the
# Markdown pages must resolve.
#
#   installed_doc_links.sh <directory or .md file>...
#
# For every page (each .md file given, and every .md file under each
# directory given) and every inline link or image [text](path#anchor) in it
# outside code (fenced blocks and `code spans` are skipped), with a path
# that is relative (not http:, mailto:, ... nor absolute):
#  - path must name an existing file or directory, relative to the page;
#  - #anchor, if the target (or, for [text](#anchor), the page itself) is a
#    Markdown page, must be the anchor of one of its headings as GitHub
#    makes them (lower case, punctuation removed, spaces to hyphens, -1, -2
#    ... for repeated headings).
# Prints a FAIL line per broken link and a PASS line per page whose links
# all resolve; exits non-zero if any link is broken or no page was found.
#
# ctest runs it as doc_links on the source tree (README.md, doc/, the
# examples' READMEs) and as installed_doc_links on the pages that
# `cmake --install` put into the prefix of the test install_package
# (share/doc/qsmpm with README.md, share/qsmpm/examples), where
# cmake/install_doc_links.cmake has rewritten the links to the installed
# targets.
set -euo pipefail

if [ $# -eq 0 ]; then
  echo "usage: $0 <directory or .md file>..." >&2
  exit 2
fi

exec perl -e '
use strict;
use warnings;
use File::Find;
use File::Basename qw(dirname);

my $failures = 0;
my @pages;
for my $arg (@ARGV) {
  if (-d $arg) {
    find({ wanted => sub { push @pages, $File::Find::name if /\.md$/ && -f $_ },
           no_chdir => 1 }, $arg);
  } elsif (-f $arg) {
    push @pages, $arg;
  } else {
    print "FAIL: $arg does not exist\n";
    ++$failures;
  }
}
if (!@pages) {
  print "FAIL: no Markdown pages found in @ARGV\n";
  exit 1;
}

# The text of a page with fenced code blocks and code spans blanked out
# (newlines kept, so that line numbers stay right).
sub prose {
  my ($file) = @_;
  open(my $in, "<", $file) or die "cannot read $file\n";
  my @lines = <$in>;
  close($in);
  my $fence = "";
  for (@lines) {
    if ($fence eq "" && /^\s*(```+|~~~+)/) { $fence = substr($1, 0, 3); $_ = "\n"; next; }
    if ($fence ne "") {
      $fence = "" if /^\s*\Q$fence\E/;
      $_ = "\n";
    }
  }
  my $text = join("", @lines);
  $text =~ s/(`+)(.+?)\1/"\n" x ($2 =~ tr{\n}{})/gse;
  return $text;
}

# The anchors of the headings of a Markdown page.
my %anchor_cache;
sub anchors {
  my ($file) = @_;
  return $anchor_cache{$file} if $anchor_cache{$file};
  my %anchors;
  my %seen;
  open(my $in, "<:encoding(UTF-8)", $file) or die "cannot read $file\n";
  my $fence = "";
  while (my $line = <$in>) {
    if ($fence eq "" && $line =~ /^\s*(```+|~~~+)/) { $fence = substr($1, 0, 3); next; }
    if ($fence ne "") { $fence = "" if $line =~ /^\s*\Q$fence\E/; next; }
    next unless $line =~ /^#{1,6}\s+(.*?)\s*#*\s*$/;
    my $heading = $1;
    $heading =~ s/!?\[([^\]]*)\]\([^)]*\)/$1/g;   # links: their text
    my $slug = lc($heading);
    $slug =~ s/[^\p{Word}\- ]//g;
    $slug =~ tr/ /-/;
    my $anchor = $seen{$slug} ? "$slug-$seen{$slug}" : $slug;
    ++$seen{$slug};
    $anchors{$anchor} = 1;
  }
  close($in);
  return $anchor_cache{$file} = \%anchors;
}

for my $page (sort @pages) {
  my $text = prose($page);
  my $directory = dirname($page);
  my ($n_links, $n_broken) = (0, 0);
  while ($text =~ /!?\[(?:[^\[\]]|\[[^\[\]]*\])*\]\(\s*<?([^()\s<>]+)>?(?:\s+"[^"]*")?\s*\)/g) {
    my $target = $1;
    my $line = 1 + (substr($text, 0, $-[0]) =~ tr/\n//);
    next if $target =~ m{^[A-Za-z][A-Za-z0-9+.-]*:};   # http:, mailto:, ...
    ++$n_links;
    my ($path, $anchor) = split(/#/, $target, 2);
    my $resolved = $path eq "" ? $page : "$directory/$path";
    my $problem;
    if ($path =~ m{^/}) {
      $problem = "absolute path";
    } elsif (!-e $resolved) {
      $problem = "no such file or directory";
    } elsif (defined $anchor && $anchor ne "" && -f $resolved && $resolved =~ /\.md$/
             && !anchors($resolved)->{$anchor}) {
      $problem = "no heading with the anchor #$anchor";
    }
    if ($problem) {
      print "FAIL: $page:$line: link ($target): $problem\n";
      ++$n_broken;
    }
  }
  if ($n_broken) {
    $failures += $n_broken;
  } else {
    print "PASS: $page: all $n_links relative links resolve\n";
  }
}
exit($failures ? 1 : 0);
' "$@"
