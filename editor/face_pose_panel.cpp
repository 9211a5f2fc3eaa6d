#include "editor/face_pose_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QToolBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

#include "anim/keyframe_clip.h"
#include "edit/content_edits.h"
#include "edit/document_edits.h"
#include "editor/character_choice.h"
#include "editor/document.h"
#include "editor/playback_clock.h"
#include "editor/qt_conversions.h"
#include "editor/session.h"
#include "runtime/stage.h"

namespace thespis::editor {

namespace {

namespace scene = core::scene;

constexpr const char* kLiveAction = "face pose editor";

// How far a FAP's slider reaches, in its unit: an eyelid closes at 1024 IRISD, the jaw opens by
// a mouth-to-nose distance and more, the eyes and head turn ±34° (60000 AU).
int fapReach(int fap)
{
    switch (scene::fapInfo(fap).unit) {
    case scene::FapUnit::IRISD: return 1100;
    case scene::FapUnit::MNS: return 800;
    case scene::FapUnit::MW: return 500;
    case scene::FapUnit::ENS: return 600;
    case scene::FapUnit::ES: return 300;
    case scene::FapUnit::AU: return 60000;
    case scene::FapUnit::None: break;
    }
    return 0;
}

bool isWeight(int channel)
{
    return channel >= scene::kFapCount;
}

std::vector<int> faps(std::initializer_list<std::pair<int, int>> ranges)
{
    std::vector<int> channels;
    for (const auto& [first, last] : ranges)
        for (int fap = first; fap <= last; ++fap)
            channels.push_back(scene::fapChannel(fap));
    return channels;
}

} // namespace

FacePosePanel::FacePosePanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("facePosePanel"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* top = new QHBoxLayout;
    m_characters = addCharacterChoice(this, top, QStringLiteral("facePoseCharacter"), tr("Whose face to pose"));
    layout->addLayout(top);
    auto* buttons = new QHBoxLayout;
    m_posingButton = new QPushButton(tr("Pose"), this);
    m_posingButton->setObjectName(QStringLiteral("facePosePlay"));
    m_posingButton->setCheckable(true);
    m_posingButton->setToolTip(tr("Show the pose on the character's face in the 3D view (close up), over what the face plays; "
                                  "the document does not change"));
    m_fromPlayhead = new QPushButton(tr("From Playhead"), this);
    m_fromPlayhead->setObjectName(QStringLiteral("facePoseFromPlayhead"));
    m_fromPlayhead->setToolTip(tr("Start from the character's face as it is at the playhead"));
    m_reset = new QPushButton(tr("Neutral"), this);
    m_reset->setObjectName(QStringLiteral("facePoseReset"));
    m_reset->setToolTip(tr("Every slider back to 0: the neutral face"));
    buttons->addWidget(m_posingButton);
    buttons->addWidget(m_fromPlayhead);
    buttons->addWidget(m_reset);
    buttons->addStretch(1);
    layout->addLayout(buttons);

    m_groups = new QToolBox(this);
    m_groups->setObjectName(QStringLiteral("facePoseGroups"));
    std::vector<int> expressions, visemes;
    for (int e = 1; e <= scene::kExpressionCount; ++e)
        expressions.push_back(scene::expressionChannel(e));
    for (int v = 1; v <= scene::kVisemeCount; ++v)
        visemes.push_back(scene::visemeChannel(v));
    addGroup(tr("Expressions"), expressions);
    addGroup(tr("Mouth and jaw"), faps({{3, 18}, {51, 60}}));
    addGroup(tr("Eyes and lids"), faps({{19, 30}}));
    addGroup(tr("Brows"), faps({{31, 38}}));
    addGroup(tr("Cheeks"), faps({{39, 42}}));
    addGroup(tr("Tongue"), faps({{43, 47}}));
    addGroup(tr("Head"), faps({{48, 50}}));
    addGroup(tr("Nose and ears"), faps({{61, 68}}));
    addGroup(tr("Visemes"), visemes);
    layout->addWidget(m_groups, 1);

    auto* saveRow = new QHBoxLayout;
    m_name = new QLineEdit(tr("face pose"), this);
    m_name->setObjectName(QStringLiteral("facePoseName"));
    m_name->setToolTip(tr("The name of the face clip (and gesture) to save"));
    m_asGesture = new QCheckBox(tr("Gesture too"), this);
    m_asGesture->setObjectName(QStringLiteral("facePoseAsGesture"));
    m_asGesture->setToolTip(tr("Also add a gesture of that name to the character's gesticon, for scripts and speech to play"));
    m_save = new QPushButton(tr("Save"), this);
    m_save->setObjectName(QStringLiteral("facePoseSave"));
    m_save->setToolTip(tr("Add the pose to the character as a face clip (one undoable step)"));
    saveRow->addWidget(new QLabel(tr("Name:"), this));
    saveRow->addWidget(m_name, 1);
    saveRow->addWidget(m_asGesture);
    saveRow->addWidget(m_save);
    layout->addLayout(saveRow);
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("facePoseMessage"));
    m_message->setWordWrap(true);
    m_message->hide();
    layout->addWidget(m_message);

    connect(m_posingButton, &QPushButton::toggled, this, [this](bool on) { setPosing(on); });
    connect(m_fromPlayhead, &QPushButton::clicked, this, &FacePosePanel::takeFromPlayhead);
    connect(m_reset, &QPushButton::clicked, this, &FacePosePanel::reset);
    connect(m_save, &QPushButton::clicked, this, [this] { save(m_name->text().trimmed(), m_asGesture->isChecked()); });
    connect(m_characters, &QComboBox::currentIndexChanged, this, [this] {
        if (m_posing) {
            stopPlaying();
            replay();
            emit closeUpRequested(currentCharacter());
        }
        updateActions();
    });
    setDocument(nullptr);
}

FacePosePanel::~FacePosePanel()
{
    // The stage must not keep a pose whose editor is gone.
    stopPlaying();
}

void FacePosePanel::addGroup(const QString& title, const std::vector<int>& channels)
{
    auto* page = new QWidget;
    auto* grid = new QGridLayout(page);
    grid->setContentsMargins(2, 2, 2, 2);
    grid->setColumnStretch(1, 1);
    int row = 0;
    for (const int channel : channels) {
        QString name, tip;
        int low = 0, high = 100;
        if (channel < scene::kFapCount) {
            const scene::FapInfo& fap = scene::fapInfo(channel + 1);
            name = fromUtf8(std::string(fap.name));
            high = fapReach(fap.number);
            low = fap.bidirectional ? -high : 0;
            tip = tr("FAP %1, in %2 units; positive: %3").arg(fap.number).arg(fromUtf8(std::string(scene::fapUnitName(fap.unit))),
                                                                               fromUtf8(std::string(fap.direction)));
        } else if (channel < scene::kFapCount + scene::kVisemeCount) {
            const int viseme = channel - scene::kFapCount + 1;
            name = tr("viseme %1").arg(fromUtf8(std::string(scene::visemeName(viseme))));
            tip = tr("Weight of MPEG-4 viseme %1, in percent").arg(viseme);
        } else {
            const int expression = channel - scene::kFapCount - scene::kVisemeCount + 1;
            name = fromUtf8(std::string(scene::expressionName(expression)));
            tip = tr("Intensity of the expression, in percent");
        }
        auto* label = new QLabel(name, page);
        auto* slider = new QSlider(Qt::Horizontal, page);
        slider->setObjectName(QStringLiteral("faceSlider%1").arg(channel));
        slider->setRange(low, high);
        slider->setToolTip(tip);
        auto* spin = new QSpinBox(page);
        spin->setRange(low, high);
        spin->setToolTip(tip);
        spin->setKeyboardTracking(false);
        grid->addWidget(label, row, 0);
        grid->addWidget(slider, row, 1);
        grid->addWidget(spin, row, 2);
        m_sliders[std::size_t(channel)] = slider;
        m_spins[std::size_t(channel)] = spin;
        const auto changed = [this, channel](int value) {
            if (!m_updating)
                setChannel(channel, isWeight(channel) ? float(value) / 100.0f : float(value));
        };
        connect(slider, &QSlider::valueChanged, this, changed);
        connect(spin, &QSpinBox::valueChanged, this, changed);
        ++row;
    }
    grid->setRowStretch(row, 1);
    m_groups->addItem(page, title);
}

void FacePosePanel::setDocument(Document* document)
{
    stopPlaying();
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    if (m_document)
        // The stage is rebuilt after an edit: the pose plays again on the new one. Queued, so
        // that the session has made its new stage first.
        connect(m_document, &Document::edited, this, [this] { QMetaObject::invokeMethod(this, [this] { replay(); }, Qt::QueuedConnection); });
    {
        const QSignalBlocker blocker(m_characters);
        fillCharacterChoice(m_characters, document);
    }
    showMessage({});
    updateActions();
}

void FacePosePanel::setSession(Session* session)
{
    stopPlaying();
    m_session = session;
    updateActions();
}

int FacePosePanel::currentCharacter() const
{
    return m_document && !m_document->scenario().characters.empty() ? m_characters->currentIndex() : -1;
}

void FacePosePanel::setCurrentCharacter(int character)
{
    if (character >= 0 && character < m_characters->count())
        m_characters->setCurrentIndex(character);
}

void FacePosePanel::setChannel(int channel, float value)
{
    if (channel < 0 || channel >= scene::kFaceChannelCount)
        return;
    const QSlider* slider = m_sliders[std::size_t(channel)];
    const float scale = isWeight(channel) ? 100.0f : 1.0f;
    value = std::clamp(value, float(slider->minimum()) / scale, float(slider->maximum()) / scale);
    if (m_pose[std::size_t(channel)] == value)
        return;
    m_pose[std::size_t(channel)] = value;
    showChannel(channel);
    replay();
}

void FacePosePanel::showChannel(int channel)
{
    const bool updating = m_updating;
    m_updating = true;
    const int value = int(std::lround(m_pose[std::size_t(channel)] * (isWeight(channel) ? 100.0f : 1.0f)));
    m_sliders[std::size_t(channel)]->setValue(value);
    m_spins[std::size_t(channel)]->setValue(value);
    m_updating = updating;
}

void FacePosePanel::setPosing(bool posing)
{
    if (posing == m_posing)
        return;
    m_posing = posing;
    {
        const QSignalBlocker blocker(m_posingButton);
        m_posingButton->setChecked(posing);
    }
    if (posing) {
        replay();
        emit closeUpRequested(currentCharacter());
    } else {
        stopPlaying();
    }
}

void FacePosePanel::takeFromPlayhead()
{
    const int c = currentCharacter();
    if (!m_session || c < 0)
        return;
    // The face at the playhead without this editor's own pose on it.
    stopPlaying();
    m_session->tick();
    const auto& poses = m_session->poses().characters;
    if (std::size_t(c) < poses.size() && poses[std::size_t(c)].face.size() == m_pose.size())
        std::copy(poses[std::size_t(c)].face.begin(), poses[std::size_t(c)].face.end(), m_pose.begin());
    for (int channel = 0; channel < scene::kFaceChannelCount; ++channel)
        showChannel(channel);
    replay();
}

void FacePosePanel::reset()
{
    m_pose.fill(0.0f);
    for (int channel = 0; channel < scene::kFaceChannelCount; ++channel)
        showChannel(channel);
    replay();
}

void FacePosePanel::replay()
{
    stopPlaying();
    const int c = currentCharacter();
    if (!m_posing || !m_session || !m_session->stage() || c < 0)
        return;
    const std::string& name = m_document->scenario().characters[std::size_t(c)].name;
    // One frame held for ever: the live action covers every face channel, so the face shows the
    // pose alone (no blinks on top while posing).
    auto clip = core::anim::KeyframeClip::create(core::anim::FrameLayout::mpeg4Face(), 1.0,
                                                 std::vector<float>(m_pose.begin(), m_pose.end()), kLiveAction);
    if (!clip) {
        showMessage(fromUtf8(clip.error().message));
        return;
    }
    core::runtime::ActionTemplate action;
    action.source = std::move(clip).value();
    action.renderOutsideDomain = true;
    if (auto played = m_session->stage()->playAction(name, core::runtime::Track::Face, kLiveAction, action,
                                                     m_session->clock()->time(), {.fadeIn = 0});
        !played) {
        showMessage(tr("Cannot show the pose: %1").arg(fromUtf8(played.error().message)));
        return;
    }
    m_playingCharacter = name;
    m_session->tick();
}

void FacePosePanel::stopPlaying()
{
    if (m_playingCharacter.empty())
        return;
    if (m_session && m_session->stage()) {
        (void)m_session->stage()->removeAction(m_playingCharacter, core::runtime::Track::Face, kLiveAction);
        m_session->tick();
    }
    m_playingCharacter.clear();
}

bool FacePosePanel::save(const QString& name, bool gesture)
{
    const int c = currentCharacter();
    if (!m_document || c < 0 || name.isEmpty()) {
        showMessage(name.isEmpty() ? tr("Give the face clip a name.") : tr("Open a scenario with a character first."));
        return false;
    }
    // The channels the pose moves, held for a second (two equal keys).
    core::scenario::ClipAsset clip;
    clip.name = name.toStdString();
    clip.frameRate = 1;
    const auto& layout = *core::anim::FrameLayout::mpeg4Face();
    std::vector<float> values;
    for (int channel = 0; channel < scene::kFaceChannelCount; ++channel)
        if (m_pose[std::size_t(channel)] != 0) {
            clip.scalars.push_back(layout.scalarNames()[std::size_t(channel)]);
            values.push_back(m_pose[std::size_t(channel)]);
        }
    if (clip.scalars.empty()) {
        showMessage(tr("The face is neutral: move a slider first."));
        return false;
    }
    clip.frames = values;
    clip.frames.insert(clip.frames.end(), values.begin(), values.end());

    auto edit = core::edit::addClips(m_document->scenario(), c, {clip});
    if (edit && gesture) {
        // The gesture names the clip as added (addClips may have made its name unique).
        core::scenario::Scenario after = m_document->scenario();
        if (auto applied = edit->apply(after); !applied) {
            showMessage(fromUtf8(applied.error().message));
            return false;
        }
        core::scenario::Gesture entry;
        entry.name = clip.name;
        entry.clip = after.characters[std::size_t(c)].clips.back().name;
        entry.fadeIn = core::secondsToTicks(0.2);
        entry.fadeOut = core::secondsToTicks(0.3);
        auto added = core::edit::addGesture(after, c, std::move(entry));
        if (!added) {
            showMessage(fromUtf8(added.error().message));
            return false;
        }
        edit->append(std::move(added).value());
    }
    if (!edit) {
        showMessage(fromUtf8(edit.error().message));
        return false;
    }
    if (auto done = m_document->edit(std::move(edit).value(), gesture ? tr("Save Face Pose as Clip and Gesture") : tr("Save Face Pose"));
        !done) {
        showMessage(fromUtf8(done.error().message));
        return false;
    }
    showMessage(tr("Saved face clip \"%1\"%2.").arg(name, gesture ? tr(" and gesture") : QString()));
    return true;
}

QString FacePosePanel::message() const
{
    return m_message->text();
}

void FacePosePanel::showMessage(const QString& message)
{
    m_message->setText(message);
    m_message->setVisible(!message.isEmpty());
}

void FacePosePanel::updateActions()
{
    const bool character = currentCharacter() >= 0;
    m_characters->setEnabled(m_characters->count() > 1);
    const bool live = character && m_session && m_session->stage();
    m_posingButton->setEnabled(live);
    m_fromPlayhead->setEnabled(live);
    m_save->setEnabled(character);
    m_name->setEnabled(character);
    m_asGesture->setEnabled(character);
}

} // namespace thespis::editor
