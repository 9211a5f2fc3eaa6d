# The paper's §4.5 script (Egges et al. 2007), as written there, with the demo scenario's
# action names: creon_wave for "creon_wrk", antigone_wave for "antigone_wrk" and creon_nod
# for the motion-synthesizer idle until idle motion lands. `animService` is given to every
# script (in the studio, `thespis-cli run` and from python3: see README.md, Scripting).

# global variables
Antigone = "Antigone"
Creon = "Creon"

# no facial animation
animService.initPlayerScope_face(False)

# start the player
animService.start_player()
animService.activateAction_body(Antigone, "antigone_idle")

# creon monologue
animService.activateAction_body(Creon, "creon_wave")
animService.waitUntilActionFinished_body(Creon, "creon_wave", -1.0)
animService.activateAction_body(Creon, "creon_nod")

# Antigone answers to Creon
animService.cutOffAction_body(Antigone, "antigone_idle", 3.0)
animService.activateAction_body(Antigone, "antigone_wave")
animService.waitUntilActionFinished_body(Antigone, "antigone_wave", -1.0)
animService.activateAction_body(Antigone, "antigone_idle")
print("Antigone answered Creon at", round(animService.now(), 2), "s")
