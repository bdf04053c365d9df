#!/usr/bin/env bash
# ctest submission:report — the report a person reads, end to end: a
# submission of Part 1 (the reference's) and a Part 3 whose light-sampling
# estimator leaves out the cosine (the mutant importance_missing_cos) is graded
# by `pt-grade submission` with renders. Then:
#  1. the library renders are flagged and the report points at part 3 alone:
#     Part 1 rendered alone with the solution for the rest must stay within
#     the noise, so a check that flags correct renders fails this test too;
#  2. each failing Part 3 image test (ImageP3) shows, beside its message
#     naming the worst region, its four images (render, reference,
#     difference, p-values), which the verifier wrote into a folder pt-grade
#     made for the run; its message in results.json sends the reader to the
#     page, and results.json holds no image and stays within its bound;
#  3. the page opens in headless Chromium with every image decoded
#     (browser/check_report_in_browser.sh; skipped without Chromium), and the
#     same check fails on a copy of the page with a broken image.
# Usage: test_report.sh PT_GRADE KIT CHECKOUT WORKDIR
set -euo pipefail
pt_grade=$1 kit=$2 source=$3 work=$4
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work/submission" "$work/out"
cp "$source/reference/part1_raygen_intersect.cpp" "$work/submission/"
part3="$work/submission/part3_direct_lighting.cpp"
cp "$source/reference/part3_direct_lighting.cpp" "$part3"
perl -pi -e 's/(L_light \+= isect\.bsdf->f\(w_out, w_in\) \* Li) \* w_in\.z \/ pdf;/$1 \/ pdf;/' "$part3"
if cmp -s "$part3" "$source/reference/part3_direct_lighting.cpp"; then
  echo "the reference line this test edits is gone (see tests/mutants/part3.cmake, importance_missing_cos)"; exit 1
fi

"$pt_grade" submission "$work/submission" --kit "$kit" --json "$work/out/results.json" \
  --html "$work/out/report.html" --work "$work" --render-seconds 120 > "$work/grade.log"
report="$work/out/report.html"

echo "== 1. the renders point at part 3"
scene_line=$(grep -A2 '<h3>cornell_spheres ' "$report" | grep 'relMSE' || true)
case "$scene_line" in
  *"far beyond what the sample count explains: look at part 3 (tasks/part3_direct_lighting.cpp)</span>"*) ;;
  *) echo "cornell_spheres is not flagged with part 3 as the suspect:"; echo "$scene_line"; exit 1 ;;
esac
if grep -q 'look at part 1\|look at the parts together\|and part 1\|look at one of' "$report"; then
  echo "a render names a suspect other than part 3 alone:"; grep -o 'look at [^<]*' "$report" | sort | uniq -c; exit 1
fi
grep -o 'look at [^<]*' "$report" | sort | uniq -c

echo "== 2. the image tests' failures, with their images"
perl -0777 -ne '
  my ($with, $without) = (0, 0);
  for my $div (split /<div class=fail>/) {
    next unless $div =~ /^<h3>P3T\d ImageP3\.(\w+)/;
    my $test = $1;
    if ($div =~ /DIFFERS from the reference; worst region (the whole|cell \(column)/ &&
        $div =~ /images in the grader&#39;s HTML report, beside this message/ &&
        $div =~ /<div class="renders test-images">((?:<figure><img alt="\w+" src="data:image\/png;base64,[A-Za-z0-9+\/=]+"><figcaption>[^<]+<\/figcaption><\/figure>){4})<\/div>/) {
      print "ImageP3.$test: region named, 4 images\n"; ++$with;
    } else {
      print "ImageP3.$test failed without its region and images:\n", substr($div, 0, 1500), "\n"; ++$without;
    }
  }
  exit($with > 0 && $without == 0 ? 0 : 1);
' "$report" || { echo "a failing image test lacks its images or its region"; exit 1; }
results="$work/out/results.json"
size=$(stat -c %s "$results")
[ "$size" -le 1000000 ] || { echo "results.json is $size bytes, over its bound"; exit 1; }
grep -q "images in the grader's HTML report, beside this message" "$results" ||
  { echo "results.json does not send an image test's reader to the report"; exit 1; }
if grep -q 'base64\|/renders/run-' "$results"; then echo "results.json holds an image or a grader's folder"; exit 1; fi
echo "results.json: $size bytes"

echo "== 3. the page in a browser"
set +e
"$here/browser/check_report_in_browser.sh" "$report" "$work/browser"
rc=$?
set -e
[ $rc -eq 77 ] && exit 77
[ $rc -eq 0 ] || exit 1
sed '0,/base64,iVBOR/s//base64,XXXXX/' "$report" > "$work/broken.html"
if "$here/browser/check_report_in_browser.sh" "$work/broken.html" "$work/browser-broken"; then
  echo "the browser check passed a page with a broken image"; exit 1
fi
echo "report OK"
