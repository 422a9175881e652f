# Sourced by the tutorial tests: moves into a scratch folder (removed on exit) holding the
# tests' freefem++.pref (from the folder the test started in) with the lessons' folder
# added, so that a lesson runs there as from any student's folder. Needs $source_dir.
pref=$PWD/freefem++.pref
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
cp "$pref" .
echo 'includepath += "'"$source_dir"'/edp/tutorial"' >> freefem++.pref
