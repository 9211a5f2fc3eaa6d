# The paper's §4.5 script (Egges et al. 2007), as written there, with the demo scenario's
# action names: creon_wave for "creon_wrk", antigone_wave for "antigone_wrk" and creon_nod
# for the motion-synthesizer idle until idle motion lands. `animService` and `voiceService` are
# given to every script (in the studio, `thespis-cli run` and from python3: see README.md,
# Scripting). The speeches are the demo characters' speech lines (Sophocles' Antigone, Jebb's
# translation), spoken by espeak-ng: unlike the paper's script, which played recorded voices with
# no face, the face plays here, and the lips move with the words. Creon's wave ("creon_wrk") is
# the greeting tagged on his first word; and, beyond the paper, the two look at each other.
# At the end Antigone is handed to the interaction service (§5.3): she takes the visitor's
# questions from her bot (dialogue/antigone), typed or spoken in the studio's Conversation dock.

# global variables
Antigone = "Antigone"
Creon = "Creon"

# facial animation: the lips follow the speech (the paper's script turned the face off)
animService.initPlayerScope_face(True)

# start the player
animService.start_player()
animService.activateAction_body(Antigone, "antigone_idle")

# they look at each other: the speaker's eyes leave the listener's more often (Eyes Alive)
animService.gaze_body(Creon, Antigone, talking=True)
animService.gaze_body(Antigone, Creon, talking=False)

# creon monologue, greeting on his first word
voiceService.activateAction(Creon, "CreonSpeech.Cam01CreonP1", 1.0)
animService.waitUntilActionFinished_face(Creon, "speech CreonSpeech.Cam01CreonP1", -0.3)
animService.activateAction_body(Creon, "creon_nod")

# Antigone answers to Creon, who listens
animService.gaze_body(Creon, Antigone, talking=False)
animService.gaze_body(Antigone, Creon, talking=True)
animService.cutOffAction_body(Antigone, "antigone_idle", 3.0)
animService.activateAction_body(Antigone, "antigone_wave")
voiceService.activateAction(Antigone, "AntigoneSpeech.Cam01CreonP3", 1.0)
animService.waitUntilActionFinished_face(Antigone, "speech AntigoneSpeech.Cam01CreonP3", -0.3)
animService.activateAction_body(Antigone, "antigone_idle")
print("Antigone answered Creon at", round(animService.now(), 2), "s")

# the act is over: Antigone takes the visitor's questions, looking at them (the camera), her idle
# motion playing on under her answers
bot = interactionService.load_bot("dialogue/antigone/antigone.aiml")
interactionService.converse(Antigone, bot)
print("Antigone takes questions: type or say them in the Conversation dock")
