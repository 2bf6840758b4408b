# Sourced by restart_case.sh and branch_case.sh: the deck variants that checkpoint every 50 steps
# and stop after 137 (between checkpoints) or resume, and the interrupted run itself.
# Expects railfe, ranks, deck and output set; the MPI launcher is passed as arguments.

# variant NAME CHECKPOINT_XML: DECK with CHECKPOINT_XML in its explicit step, as OUTPUT/NAME.xml.
variant() {
  sed "s#<Parameter name=\"Module\" type=\"string\" value=\"explicit\"/>#&$2#" "$deck" \
    >"$output/$1.xml"
}

# write_checkpoint_variants: OUTPUT/interrupted.xml and OUTPUT/resumed.xml.
write_checkpoint_variants() {
  variant interrupted '<ParameterList name="Checkpoint"><Parameter name="Interval" type="int" value="50"/><Parameter name="Stop after steps" type="int" value="137"/></ParameterList>'
  variant resumed '<ParameterList name="Checkpoint"><Parameter name="Interval" type="int" value="50"/><Parameter name="Restart" type="bool" value="true"/></ParameterList>'
}

# run_interrupted LAUNCHER...: runs interrupted.xml into OUTPUT/resumed; exits the script with a
# FAIL line unless it stopped after 137 steps.
run_interrupted() {
  "$@" -np "$ranks" "$railfe" "$output/interrupted.xml" --output "$output/resumed" --quiet \
    >"$output/interrupted.log" 2>&1
  if ! grep -q "stopped after 137 steps" "$output/interrupted.log"; then
    cat "$output/interrupted.log"
    echo "FAIL: the interrupted run did not stop after 137 steps"
    exit 1
  fi
}
