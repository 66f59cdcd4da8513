# gtkwave_probe.tcl - run by GTKWave (gtkwave -S gtkwave_probe.tcl FILE.gtkw) for cli.gtkwave_trace:
# prints the rows shown and the time window as GTKWave has them, then quits GTKWave.
# Pump GTK's main loop so that the window has its size before the window is read.
for {set i 0} {$i < 20} {incr i} { gtkwave::nop }
set n [gtkwave::getVisibleNumTraces]
puts "PROBE rows $n"
for {set i 0} {$i < $n} {incr i} { puts "PROBE row [gtkwave::getTraceNameFromIndex $i]" }
puts "PROBE start [gtkwave::getWindowStartTime]"
puts "PROBE end [gtkwave::getWindowEndTime]"
puts "PROBE max [gtkwave::getMaxTime]"
gtkwave::/File/Quit
