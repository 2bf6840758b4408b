# Sourced by restart_case.sh and branch_case.sh: the deck variants that checkpoint every
# RESTART_INTERVAL steps (50 unless set) and stop 37 steps after the second checkpoint or resume
# from it, and the interrupted run itself.
# Expects railfe, ranks, deck and output set; the MPI launcher is passed as arguments.

checkpoint_interval=${RESTART_INTERVAL:-50}
stop_after=$((2 * checkpoint_interval + 37))
# The step the resumed run starts from.
resume_step=$((2 * checkpoint_interval))

# variant NAME CHECKPOINT_XML: DECK with CHECKPOINT_XML in its explicit step, as OUTPUT/NAME.xml.
# A relative mesh File is made absolute (the variant lives elsewhere); RESTART_END_TIME and
# RESTART_PATCH_TIMES, when set, replace the End time and the contact Patch times (a long
# verification deck cut to a few hundred steps).
variant() {
  local deck_dir
  deck_dir=$(cd "$(dirname "$deck")" && pwd)
  local edits=(
    -e "s#<Parameter name=\"Module\" type=\"string\" value=\"explicit\"/>#&$2#"
    -e "s#\(<Parameter name=\"File\" type=\"string\" value=\"\)\([^/\"][^\"]*\"\)#\1$deck_dir/\2#")
  [ -n "${RESTART_END_TIME:-}" ] && edits+=(
    -e "s#\(<Parameter name=\"End time\" type=\"double\" value=\"\)[^\"]*\"#\1$RESTART_END_TIME\"#")
  [ -n "${RESTART_PATCH_TIMES:-}" ] && edits+=(
    -e "s#\(<Parameter name=\"Patch times\" type=\"Array(double)\" value=\"\)[^\"]*\"#\1$RESTART_PATCH_TIMES\"#")
  sed "${edits[@]}" "$deck" >"$output/$1.xml"
}

# write_checkpoint_variants: OUTPUT/interrupted.xml and OUTPUT/resumed.xml.
write_checkpoint_variants() {
  variant interrupted '<ParameterList name="Checkpoint"><Parameter name="Interval" type="int" value="'$checkpoint_interval'"/><Parameter name="Stop after steps" type="int" value="'$stop_after'"/></ParameterList>'
  variant resumed '<ParameterList name="Checkpoint"><Parameter name="Interval" type="int" value="'$checkpoint_interval'"/><Parameter name="Restart" type="bool" value="true"/></ParameterList>'
}

# run_interrupted LAUNCHER...: runs interrupted.xml into OUTPUT/resumed; exits the script with a
# FAIL line unless it stopped after stop_after steps.
run_interrupted() {
  "$@" -np "$ranks" "$railfe" "$output/interrupted.xml" --output "$output/resumed" --quiet \
    >"$output/interrupted.log" 2>&1
  if ! grep -q "stopped after $stop_after steps" "$output/interrupted.log"; then
    cat "$output/interrupted.log"
    echo "FAIL: the interrupted run did not stop after $stop_after steps"
    exit 1
  fi
}

# same_diagnostics A B: the contact pairs' penalty flexibility lines (the ratio and the patch's
# semi-axes at the largest normal force) of summary A equal those of B; exits the script with a
# FAIL line otherwise. The checkpoint carries them, so a resumed run reports what an
# uninterrupted one does although it did not see the rows before its restart.
same_diagnostics() {
  local pattern="penalty tangential flexibility|patch semi-axes"
  if ! diff <(grep -E "$pattern" "$1") <(grep -E "$pattern" "$2"); then
    echo "FAIL: $2 reports another penalty flexibility than $1"
    exit 1
  fi
}
