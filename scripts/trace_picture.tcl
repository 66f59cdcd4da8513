# trace_picture.tcl - run by GTKWave for scripts/trace_picture.sh: lets the window take its size,
# writes the window to trace.png (GTKWave's File > Grab To File) and quits.
for {set i 0} {$i < 40} {incr i} { gtkwave::nop }
gtkwave::/File/Grab_To_File trace.png
gtkwave::/File/Quit
