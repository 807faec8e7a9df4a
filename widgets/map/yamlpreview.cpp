// SPDX-License-Identifier: MIT
#include "yamlpreview.h"

#include "config/configdocument.h"
#include "config/mqttclientrelease.h"
#include "widgets/common/chartstyle.h"

#include <QComboBox>
#include <QEvent>
#include <QFontDatabase>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QScrollBar>
#include <QSyntaxHighlighter>
#include <QTextBlock>
#include <QTimer>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

/// Keys, comments and substitutions in colour, so that the structure reads at a glance.
class YamlHighlighter : public QSyntaxHighlighter
{
public:
    using QSyntaxHighlighter::QSyntaxHighlighter;
    /// Colours that read on a dark background, or on a light one.
    void setDark(bool dark)
    {
        if (dark == m_dark)
            return;
        m_dark = dark;
        rehighlight();
    }
    bool isDark() const { return m_dark; }

protected:
    void highlightBlock(const QString& text) override
    {
        static const QRegularExpression key(uR"(^\s*(- )?([^\s#:][^#:]*):(\s|$))"_s);
        static const QRegularExpression comment(uR"((^|\s)#.*$)"_s);
        static const QRegularExpression substitution(uR"(\$\([^)]*\))"_s);
        QTextCharFormat keyFormat;
        keyFormat.setForeground(m_dark ? QColor(0x8a, 0xb4, 0xf8) : QColor(0x1f, 0x5f, 0xa8));
        keyFormat.setFontWeight(QFont::DemiBold);
        QTextCharFormat commentFormat;
        commentFormat.setForeground(m_dark ? QColor(0x9a, 0xa0, 0xa6) : QColor(0x6a, 0x73, 0x7d));
        commentFormat.setFontItalic(true);
        QTextCharFormat subFormat;
        subFormat.setForeground(m_dark ? QColor(0xd7, 0xae, 0xfb) : QColor(0x8a, 0x3f, 0xa0));
        if (const auto m = key.match(text); m.hasMatch())
            setFormat(int(m.capturedStart(2)), int(m.capturedLength(2)), keyFormat);
        for (auto it = substitution.globalMatch(text); it.hasNext();) {
            const auto m = it.next();
            setFormat(int(m.capturedStart()), int(m.capturedLength()), subFormat);
        }
        if (const auto m = comment.match(text); m.hasMatch())
            setFormat(int(m.capturedStart()), int(m.capturedLength()), commentFormat);
    }

private:
    bool m_dark = false;
};

YamlPreview::YamlPreview(ConfigDocument* document, QWidget* parent)
    : QWidget(parent)
    , m_doc(document)
    , m_timer(new QTimer(this))
{
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    auto* h = new QHBoxLayout;
    m_layout = new QComboBox(this);
    m_layout->setObjectName(u"previewLayout"_s);
    m_layout->addItem(tr("mqtt_client, ROS 1"), int(ConfigLayout::Ros1));
    m_layout->addItem(tr("mqtt_client, ROS 2"), int(ConfigLayout::Ros2));
    m_layout->addItem(tr("mqtt_bridge"), int(ConfigLayout::MqttBridge));
    auto* label = new QLabel(tr("&Layout:"), this);
    label->setBuddy(m_layout);
    h->addWidget(label);
    h->addWidget(m_layout);
    h->addStretch(1);
    v->addLayout(h);
    m_note = new QLabel(this);
    m_note->setWordWrap(true);
    v->addWidget(m_note);
    m_text = new QPlainTextEdit(this);
    m_text->setObjectName(u"previewText"_s);
    m_text->setReadOnly(true);
    m_text->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_text->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_highlighter = new YamlHighlighter(m_text->document());
    m_highlighter->setDark(ChartStyle::isDark(palette()));
    v->addWidget(m_text, 1);

    // Quick edits arrive one after another; the preview is computed once they pause.
    m_timer->setSingleShot(true);
    m_timer->setInterval(150);
    // A large config takes a moment to render; do it only while the preview can be seen.
    connect(m_timer, &QTimer::timeout, this, [this] {
        if (isVisible())
            refreshNow();
        else
            m_stale = true;
    });
    auto later = [this] { m_timer->start(); };
    connect(m_doc, &ConfigDocument::problemsChanged, this, later);
    connect(m_doc, &ConfigDocument::resetDone, this, [this] {
        setLayout(m_doc->layout());
        m_timer->start();
    });
    connect(m_doc, &ConfigDocument::layoutChanged, this, [this](ConfigLayout l) { setLayout(l); });
    connect(m_layout, &QComboBox::currentIndexChanged, this, later);
    m_stale = true;
}

void YamlPreview::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    if (m_stale)
        refreshNow();
}

ConfigLayout YamlPreview::layout() const
{
    return ConfigLayout(m_layout->currentData().toInt());
}

void YamlPreview::setLayout(ConfigLayout layout)
{
    m_layout->setCurrentIndex(m_layout->findData(int(layout)));
}

QString YamlPreview::text() const
{
    return m_text->toPlainText();
}

void YamlPreview::refreshNow()
{
    m_timer->stop();
    m_stale = false;
    m_layout->setEnabled(!m_doc->isReadOnly());
    if (m_doc->isReadOnly()) {
        showReadOnly();
        return;
    }
    m_text->setExtraSelections({});
    m_errorLine = -1;
    m_note->setStyleSheet(QString());
    bool keeps = false;
    QStringList notes;
    const QString yaml = m_doc->preview(layout(), &keeps, &notes);
    QStringList lines;
    if (m_doc->hasFileText()) {
        lines << (keeps ? tr("Saving edits the file in place: comments and formatting are kept.")
                        : tr("Saving in this layout writes the file anew: its comments are not kept."));
    }
    lines += notes;
    lines << MqttClientReleases::summary(m_doc->config(), m_doc->validationOptions().target);
    m_note->setText(lines.join(u'\n'));
    m_note->setVisible(!lines.isEmpty());
    // Keep the reader's place when the text is replaced.
    const int scroll = m_text->verticalScrollBar() ? m_text->verticalScrollBar()->value() : 0;
    m_text->setPlainText(yaml);
    m_text->verticalScrollBar()->setValue(scroll);
}

void YamlPreview::showReadOnly()
{
    const ConfigDocument::ReadOnlyView& view = m_doc->readOnlyView();
    const QLocale locale;
    QStringList lines {tr("Read-only: this file cannot be edited or saved here, because it is not a "
                          "bridge config Bridgescope can read. Fix it in a text editor and open it again.")};
    const TextPos at = view.errorPos;
    lines << (at.isValid() ? tr("Line %1, column %2: %3").arg(at.line + 1).arg(at.column + 1).arg(view.reason)
                           : view.reason);
    if (view.truncated)
        lines << tr("Only the first %1 of %2 are shown.")
                     .arg(locale.formattedDataSize(view.text.toUtf8().size(), 1,
                                                   QLocale::DataSizeTraditionalFormat),
                          locale.formattedDataSize(view.fileSize, 1, QLocale::DataSizeTraditionalFormat));
    m_text->setPlainText(view.text);
    QList<QTextEdit::ExtraSelection> marks;
    const QTextBlock block = at.isValid() ? m_text->document()->findBlockByNumber(at.line) : QTextBlock();
    if (block.isValid()) {
        // The whole line tinted, the place itself underlined, the cursor on it.
        QTextEdit::ExtraSelection line;
        line.format.setBackground(ChartStyle::isDark(palette()) ? QColor(0x5c, 0x1f, 0x1f)
                                                                : QColor(0xfd, 0xe2, 0xe2));
        line.format.setProperty(QTextFormat::FullWidthSelection, true);
        line.cursor = QTextCursor(block);
        QTextEdit::ExtraSelection place;
        place.format.setUnderlineStyle(QTextCharFormat::WaveUnderline);
        place.format.setUnderlineColor(Qt::red);
        place.cursor = QTextCursor(block);
        place.cursor.movePosition(QTextCursor::Right, QTextCursor::MoveAnchor,
                                  std::min(at.column, std::max(0, block.length() - 2)));
        place.cursor.movePosition(QTextCursor::Right, QTextCursor::KeepAnchor);
        marks << line << place;
        m_text->setTextCursor(place.cursor);
        m_text->centerCursor();
    } else if (at.isValid()) {
        lines << tr("Line %1 is past the part shown.").arg(at.line + 1);
    }
    m_text->setExtraSelections(marks);
    m_errorLine = block.isValid() ? block.blockNumber() : -1;
    m_note->setText(lines.join(u'\n'));
    m_note->setStyleSheet(u"font-weight: bold"_s);
    m_note->setVisible(true);
}

QString YamlPreview::note() const
{
    return m_note->isVisible() ? m_note->text() : QString();
}

void YamlPreview::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange)
        m_highlighter->setDark(ChartStyle::isDark(palette()));
}

bool YamlPreview::isDarkHighlighting() const
{
    return m_highlighter->isDark();
}
