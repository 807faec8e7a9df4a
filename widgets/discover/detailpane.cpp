// SPDX-License-Identifier: MIT
#include "detailpane.h"

#include "models/mqtttopictree.h"
#include "session/fieldplotter.h"
#include "session/graphstatus.h"
#include "topics/topictablemodel.h"
#include "widgets/common/ratechart.h"
#include "widgets/discover/fieldplotchart.h"
#include "wire/fieldpath.h"
#include "wire/rosmessage.h"
#include "wire/sourcemessage.h"

#include <cmath>
#include <QAction>
#include <QComboBox>
#include <QDateTime>
#include <QEvent>
#include <QFontDatabase>
#include <QHeaderView>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QListWidget>
#include <QLocale>
#include <QPixmap>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QTableWidget>
#include <QTabWidget>
#include <QTextLayout>
#include <QTreeView>
#include <QVBoxLayout>

using namespace Qt::StringLiterals;

namespace {
QString sizeText(qint64 bytes)
{
    return QLocale::system().formattedDataSize(bytes, 1, QLocale::DataSizeTraditionalFormat);
}

QList<QStandardItem*> row(const QString& name, const QString& value, const QString& type,
                          const QStringList& path = {}, bool numeric = false)
{
    auto* n = new QStandardItem(name);
    auto* v = new QStandardItem(value);
    auto* t = new QStandardItem(type);
    for (QStandardItem* i : {n, v, t})
        i->setEditable(false);
    n->setData(path, DetailPane::FieldPathRole);
    n->setData(numeric, DetailPane::NumericRole);
    return {n, v, t};
}

void addValue(QStandardItem* parent, const RosValue& value, const QStringList& parentPath)
{
    QString text;
    if (value.kind == RosValue::Scalar)
        text = value.value.toString() + (value.truncated ? u"…"_s : QString());
    else if (value.kind == RosValue::Array)
        text = value.value.isValid()
            ? DetailPane::tr("%1 bytes: %2%3")
                  .arg(value.arrayLength)
                  .arg(value.value.toString(), value.truncated ? u" …"_s : QString())
            : DetailPane::tr("%1 elements%2")
                  .arg(value.arrayLength)
                  .arg(value.truncated ? DetailPane::tr(", first %1 shown").arg(value.children.size())
                                       : QString());
    const QStringList path = parentPath + QStringList {value.name};
    QList<QStandardItem*> items = row(value.name, text, value.type, path,
                                      value.kind == RosValue::Scalar && FieldPath::isNumericType(value.type));
    for (const RosValue& c : value.children)
        addValue(items.first(), c, path);
    parent->appendRow(items);
}

/// The rows a JSON payload's fields may take in all (a row costs a few hundred bytes and its share of
/// every repaint); past them the rest is not shown, and a last row says how much.
constexpr int kMaxJsonRows = 5000;
/// A JSON payload larger than this is not parsed for fields (its text is still shown, cut).
constexpr qsizetype kMaxJsonFieldsBytes = 4 * 1024 * 1024;

// `path` is the value's own path: empty for a document's root array, shown as "(root)". `rows` is
// what is left of kMaxJsonRows.
void addJson(QStandardItem* parent, const QString& name, const QJsonValue& v, const QStringList& path,
             int& rows)
{
    if (rows <= 0)
        return;
    --rows;
    QList<QStandardItem*> items;
    const auto more = [&](qsizetype left) {
        if (left > 0)
            items.first()->appendRow(
                row(u"…"_s, DetailPane::tr("%n more not shown", nullptr, int(left)), QString(), path));
    };
    if (v.isObject()) {
        items = row(name, QString(), u"object"_s, path);
        const QJsonObject o = v.toObject();
        qsizetype shown = 0;
        for (auto it = o.begin(); it != o.end() && rows > 0; ++it, ++shown)
            addJson(items.first(), it.key(), it.value(), path + QStringList {it.key()}, rows);
        more(o.size() - shown);
    } else if (v.isArray()) {
        const QJsonArray a = v.toArray();
        items = row(name, DetailPane::tr("%1 elements").arg(a.size()), u"array"_s, path);
        qsizetype shown = 0;
        for (; shown < a.size() && shown < 256 && rows > 0; ++shown)
            addJson(items.first(), u"[%1]"_s.arg(shown), a[shown], path + QStringList {u"[%1]"_s.arg(shown)},
                    rows);
        more(a.size() - shown);
    } else {
        const QString type = v.isString() ? u"string"_s
            : v.isBool()                  ? u"bool"_s
            : v.isNull()                  ? u"null"_s
                                          : u"number"_s;
        items = row(name,
                    v.isString()
                        ? v.toString()
                        : QString::fromUtf8(QJsonDocument(QJsonArray {v}).toJson(QJsonDocument::Compact))
                              .mid(1)
                              .chopped(1),
                    type, path, !path.isEmpty() && (v.isBool() || v.isDouble()));
    }
    parent->appendRow(items);
}
} // namespace

DetailPane::DetailPane(const Parts& parts, QWidget* parent)
    : QWidget(parent)
    , m_parts(parts)
    , m_title(new QLabel(this))
    , m_tabs(new QTabWidget(this))
    , m_fields(new QTreeView(this))
    , m_fieldModel(new QStandardItemModel(this))
    , m_mode(new QComboBox(this))
    , m_payloadNote(new QLabel(this))
    , m_payload(new QPlainTextEdit(this))
    , m_history(new QTableWidget(this))
    , m_rate(new RateChart(this))
    , m_broker(new QTableWidget(this))
    , m_plotter(new FieldPlotter(parts.live, this))
    , m_plotChart(new FieldPlotChart(this))
    , m_plotList(new QListWidget(this))
    , m_plotSeconds(new QSpinBox(this))
    , m_plotPoints(new QSpinBox(this))
    , m_plotNote(new QLabel(this))
    , m_plotAction(new QAction(tr("&Plot Field"), this))
{
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    m_title->setWordWrap(true);
    m_title->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_title->setText(tr("Select a ROS or MQTT topic to see what it carries."));
    v->addWidget(m_title);
    v->addWidget(m_tabs, 1);
    m_tabs->setElideMode(Qt::ElideNone); // `B…` told nothing; a narrow pane scrolls its tabs
    m_tabs->setUsesScrollButtons(true);

    m_payloadNote->setObjectName(u"payloadNote"_s);
    m_plotter->setObjectName(u"fieldPlotter"_s);
    m_plotNote->setObjectName(u"plotNote"_s);
    m_plotAction->setObjectName(u"plotAction"_s);
    m_fields->setObjectName(u"fields"_s);
    m_fields->setModel(m_fieldModel);
    m_fields->setUniformRowHeights(true);
    m_fieldModel->setHorizontalHeaderLabels({tr("Field"), tr("Value"), tr("Type")});
    m_tabs->addTab(m_fields, tr("&Fields"));

    auto* payloadPage = new QWidget(this);
    auto* pv = new QVBoxLayout(payloadPage);
    pv->setContentsMargins(0, 0, 0, 0);
    m_mode->addItem(tr("Automatic"), int(PayloadText::Mode::Auto));
    m_mode->addItem(tr("Text"), int(PayloadText::Mode::Text));
    m_mode->addItem(tr("JSON"), int(PayloadText::Mode::Json));
    m_mode->addItem(tr("Hex"), int(PayloadText::Mode::Hex));
    auto* modeRow = new QHBoxLayout;
    auto* modeLabel = new QLabel(tr("&Show as:"), payloadPage);
    modeLabel->setBuddy(m_mode);
    modeRow->addWidget(modeLabel);
    modeRow->addWidget(m_mode);
    modeRow->addWidget(m_payloadNote, 1);
    pv->addLayout(modeRow);
    m_payload->setObjectName(u"payload"_s);
    m_payload->setReadOnly(true);
    m_payload->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_payload->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    pv->addWidget(m_payload, 1);
    m_tabs->addTab(payloadPage, tr("&Payload"));
    connect(m_mode, &QComboBox::currentIndexChanged, this, [this] { showPayload(m_lastPayload); });

    m_history->setColumnCount(3);
    m_history->setHorizontalHeaderLabels({tr("Received"), tr("Size"), tr("Retained")});
    m_history->horizontalHeader()->setStretchLastSection(true);
    m_history->verticalHeader()->hide();
    m_history->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_tabs->addTab(m_history, tr("&History"));
    m_tabs->addTab(m_rate, tr("&Rate"));
    m_tabs->addTab(createPlotTab(), tr("P&lot"));

    m_broker->setColumnCount(2);
    m_broker->setHorizontalHeaderLabels({tr("$SYS topic"), tr("Value")});
    m_broker->horizontalHeader()->setStretchLastSection(true);
    m_broker->verticalHeader()->hide();
    m_broker->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_tabs->addTab(m_broker, tr("&Broker"));
    connect(parts.live.mqttTopics, &MqttTopicTree::brokerStatisticsChanged, this, [this] {
        if (m_tabs->currentWidget() == m_broker)
            refreshBroker();
    });
    connect(m_tabs, &QTabWidget::currentChanged, this, [this] {
        if (m_tabs->currentWidget() == m_broker)
            refreshBroker();
        if (m_tabs->currentWidget() == m_plotChart->parentWidget())
            m_plotChart->setSeries(m_plotter->series(), m_plotter->nowSeconds());
    });
}

/// Fields picked in the Fields tab (context menu or Ctrl+L), over time; removable one by one.
QWidget* DetailPane::createPlotTab()
{
    m_plotAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_L));
    m_plotAction->setShortcutContext(Qt::WidgetShortcut);
    m_plotAction->setToolTip(tr("Plot the selected numeric field over time (Ctrl+L)"));
    m_plotAction->setEnabled(false);
    m_fields->addAction(m_plotAction);
    m_fields->setContextMenuPolicy(Qt::ActionsContextMenu);
    connect(m_plotAction, &QAction::triggered, this, [this] { plotField(m_fields->currentIndex()); });
    connect(m_fields->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex& i) {
                m_plotAction->setEnabled(i.siblingAtColumn(0).data(NumericRole).toBool());
            });

    auto* page = new QWidget(this);
    auto* v = new QVBoxLayout(page);
    v->setContentsMargins(0, 0, 0, 0);
    m_plotChart->setObjectName(u"plotChart"_s);
    v->addWidget(m_plotChart, 1);
    // The legend: each field's colour and its whole name, wrapped rather than cut.
    m_plotList->setObjectName(u"plotList"_s);
    m_plotList->setMaximumHeight(110);
    m_plotList->setWordWrap(true);
    m_plotList->setTextElideMode(Qt::ElideNone);
    m_plotList->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_plotList->viewport()->installEventFilter(this); // a new width wraps the names anew
    v->addWidget(m_plotList);
    v->addLayout(createBufferRow(page));
    auto* buttons = new QHBoxLayout;
    auto* remove = new QPushButton(tr("Remo&ve"), page);
    remove->setToolTip(tr("Stop plotting the selected field (Del in the list)"));
    auto* removeKey = new QAction(this);
    removeKey->setShortcut(QKeySequence::Delete);
    removeKey->setShortcutContext(Qt::WidgetShortcut);
    m_plotList->addAction(removeKey);
    auto* clear = new QPushButton(tr("Clear &All"), page);
    m_plotNote->setWordWrap(true);
    buttons->addWidget(m_plotNote, 1);
    buttons->addWidget(remove);
    buttons->addWidget(clear);
    v->addLayout(buttons);
    const auto removeCurrent = [this] { m_plotter->remove(m_plotList->currentRow()); };
    connect(remove, &QPushButton::clicked, this, removeCurrent);
    connect(removeKey, &QAction::triggered, this, removeCurrent);
    connect(clear, &QPushButton::clicked, m_plotter, &FieldPlotter::clear);
    connect(m_plotter, &FieldPlotter::updated, this, &DetailPane::showPlots);
    connect(m_plotter, &FieldPlotter::fieldsChanged, this, &DetailPane::showPlots);
    showPlots();
    return page;
}

/// How much each field keeps, as the user sets it (remembered), within the memory budget.
QBoxLayout* DetailPane::createBufferRow(QWidget* page)
{
    QSettings settings;
    m_plotSeconds->setObjectName(u"plotSeconds"_s);
    m_plotSeconds->setRange(FieldPlotter::kMinSeconds, FieldPlotter::kMaxSeconds);
    m_plotSeconds->setSuffix(tr(" s"));
    m_plotSeconds->setValue(settings.value(u"discover/plotSeconds"_s, FieldPlotter::kDefaultSeconds).toInt());
    m_plotPoints->setObjectName(u"plotPoints"_s);
    m_plotPoints->setRange(FieldPlotter::kMinPointsPerField, FieldPlotter::kMaxPointsPerField);
    m_plotPoints->setGroupSeparatorShown(true);
    m_plotPoints->setSingleStep(10'000);
    m_plotPoints->setValue(
        settings.value(u"discover/plotPoints"_s, FieldPlotter::kDefaultPointsPerField).toInt());
    auto* keep = new QLabel(tr("&Keep the last"), page);
    keep->setBuddy(m_plotSeconds);
    auto* points = new QLabel(tr("and at &most"), page);
    points->setBuddy(m_plotPoints);
    auto* spins = new QHBoxLayout;
    spins->addWidget(keep);
    spins->addWidget(m_plotSeconds);
    spins->addWidget(points);
    spins->addWidget(m_plotPoints);
    spins->addStretch(1);
    // The sentence goes on below: the row stays narrow enough for the pane's share of 1280 px.
    auto* bound = new QLabel(tr("points per field (%L1 at most: %2 MiB for %3 fields)")
                                 .arg(FieldPlotter::kMaxPointsPerField)
                                 .arg(FieldPlotter::kMemoryBudgetBytes / (1024 * 1024))
                                 .arg(FieldPlotter::kMaxFields),
                             page);
    bound->setWordWrap(true);
    auto* row = new QVBoxLayout;
    row->addLayout(spins);
    row->addWidget(bound);
    const auto apply = [this] {
        m_plotter->setBuffer(m_plotSeconds->value(), m_plotPoints->value());
        m_plotChart->setBufferSeconds(m_plotter->bufferSeconds());
        QSettings settings;
        settings.setValue(u"discover/plotSeconds"_s, m_plotter->bufferSeconds());
        settings.setValue(u"discover/plotPoints"_s, m_plotter->bufferPoints());
    };
    m_plotter->setBuffer(m_plotSeconds->value(), m_plotPoints->value());
    m_plotChart->setBufferSeconds(m_plotter->bufferSeconds());
    connect(m_plotSeconds, &QSpinBox::valueChanged, this, apply);
    connect(m_plotPoints, &QSpinBox::valueChanged, this, apply);
    return row;
}

int DetailPane::wrappedHeight(const QString& text, const QFont& font, int width)
{
    // As the item delegate wraps: at word boundaries, and anywhere in a word wider than the line.
    QTextLayout layout(text, font);
    QTextOption option;
    option.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    layout.setTextOption(option);
    layout.beginLayout();
    qreal height = 0;
    for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
        line.setLineWidth(width);
        height += line.height();
    }
    layout.endLayout();
    return int(std::ceil(height));
}

void DetailPane::fitLegend()
{
    const int width = m_plotList->viewport()->width();
    const int text = std::max(40, width - m_plotList->iconSize().width() - kLegendMargins);
    for (int i = 0; i < m_plotList->count(); ++i) {
        QListWidgetItem* item = m_plotList->item(i);
        const QSize size(width, wrappedHeight(item->text(), m_plotList->font(), text) + 4);
        if (item->sizeHint() != size)
            item->setSizeHint(size);
    }
}

bool DetailPane::eventFilter(QObject* watched, QEvent* event)
{
    if (watched == m_plotList->viewport() && event->type() == QEvent::Resize)
        fitLegend();
    return QWidget::eventFilter(watched, event);
}

bool DetailPane::plotField(const QModelIndex& index)
{
    const QModelIndex name = index.siblingAtColumn(0);
    if (!name.data(NumericRole).toBool() || m_kind == Kind::None)
        return false;
    PlotField field;
    field.source = m_kind == Kind::Ros2 ? PlotField::Source::Ros2
        : m_kind == Kind::Ros           ? PlotField::Source::Ros
                                        : PlotField::Source::Mqtt;
    field.topic = m_topic;
    field.path = name.data(FieldPathRole).toStringList();
    if (!m_plotter->add(field) && m_plotter->indexOf(field) < 0) {
        m_plotNote->setText(tr("At most %1 fields are plotted at once.").arg(FieldPlotter::kMaxFields));
        return false;
    }
    return true;
}

/// Once per tick with new points: the chart, and each field's count of errors.
void DetailPane::showPlots()
{
    const QList<PlotSeries>& series = m_plotter->series();
    if (m_tabs->currentWidget() == m_plotChart->parentWidget() || series.isEmpty())
        m_plotChart->setSeries(series, m_plotter->nowSeconds());
    if (m_plotList->count() != series.size()) {
        m_plotList->clear();
        for (int i = 0; i < series.size(); ++i)
            m_plotList->addItem(QString());
    }
    for (int i = 0; i < series.size(); ++i) {
        const PlotSeries& s = series[i];
        QListWidgetItem* item = m_plotList->item(i);
        const QString text = s.errors
            ? tr("%1 (%2 messages without a value: %3)").arg(s.label).arg(s.errors).arg(s.lastError)
            : s.label;
        if (item->text() != text)
            item->setText(text);
        if (item->icon().isNull()) {
            QPixmap swatch(16, 16);
            swatch.fill(FieldPlotChart::colour(i));
            item->setIcon(QIcon(swatch));
        }
    }
    fitLegend();
    if (series.isEmpty())
        m_plotNote->setText(
            tr("Select a number in Fields and press Ctrl+L (or Plot Field in its context menu)."));
    else if (m_plotter->skippedMessages())
        m_plotNote->setText(tr("%1 messages not decoded to keep up (at most %2 per topic and tick are).")
                                .arg(m_plotter->skippedMessages())
                                .arg(FieldPlotter::kMessagesPerTick));
    else
        m_plotNote->clear();
}

void DetailPane::showRosTopic(const QString& topic)
{
    m_kind = Kind::Ros;
    m_topic = topic;
    m_shownMessages = ~0ull;
    m_rosRates.clear();
    refreshRos(true);
}

void DetailPane::showRos2Topic(const QString& topic)
{
    m_kind = Kind::Ros2;
    m_topic = topic;
    m_shownMessages = ~0ull;
    m_rosRates.clear();
    refreshRos(true);
}

void DetailPane::showMqttTopic(const QString& topic)
{
    m_kind = Kind::Mqtt;
    m_topic = topic;
    m_shownMessages = ~0ull;
    refreshMqtt(true);
}

void DetailPane::refresh()
{
    if (m_kind == Kind::Mqtt)
        refreshMqtt(false);
    else if (m_kind == Kind::Ros || m_kind == Kind::Ros2)
        refreshRos(false);
}

QStringList DetailPane::clearFields()
{
    const QStringList current
        = m_fields->currentIndex().siblingAtColumn(0).data(FieldPathRole).toStringList();
    m_fieldModel->removeRows(0, m_fieldModel->rowCount());
    return current;
}

/// The field that was current before a refresh is current again (to plot it, or read on).
void DetailPane::restoreCurrentField(const QStringList& path)
{
    if (path.isEmpty())
        return;
    const QModelIndexList found = m_fieldModel->match(m_fieldModel->index(0, 0), FieldPathRole, path, 1,
                                                      Qt::MatchExactly | Qt::MatchRecursive);
    if (!found.isEmpty())
        m_fields->selectionModel()->setCurrentIndex(
            found.first(), QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
}

void DetailPane::showNoFields(const QString& why)
{
    clearFields();
    m_fieldModel->invisibleRootItem()->appendRow(row(why, QString(), QString()));
}

void DetailPane::showFields(const RosValue& value)
{
    const QStringList current = clearFields();
    for (const RosValue& c : value.children)
        addValue(m_fieldModel->invisibleRootItem(), c, {});
    m_fields->expandToDepth(1);
    restoreCurrentField(current);
    m_fields->resizeColumnToContents(0);
    m_fields->resizeColumnToContents(1);
}

void DetailPane::showJsonFields(const QByteArray& json)
{
    const QJsonDocument doc = QJsonDocument::fromJson(json);
    const QStringList current = clearFields();
    int rows = kMaxJsonRows;
    if (doc.isObject()) {
        const QJsonObject o = doc.object();
        for (auto it = o.begin(); it != o.end() && rows > 0; ++it)
            addJson(m_fieldModel->invisibleRootItem(), it.key(), it.value(), {it.key()}, rows);
        if (rows <= 0)
            m_fieldModel->appendRow(
                row(u"…"_s, tr("at most %1 fields are shown").arg(kMaxJsonRows), QString(), {}));
    } else {
        addJson(m_fieldModel->invisibleRootItem(), u"(root)"_s,
                doc.isArray() ? QJsonValue(doc.array()) : QJsonValue(), {}, rows);
    }
    m_fields->expandToDepth(1);
    restoreCurrentField(current);
    m_fields->resizeColumnToContents(0);
}

void DetailPane::showPayload(const QByteArray& payload)
{
    const auto mode = PayloadText::Mode(m_mode->currentData().toInt());
    const PayloadText::Rendered r = PayloadText::render(payload, mode);
    m_payload->setPlainText(r.text);
    m_payloadNote->setText(r.note);
}

void DetailPane::refreshMqtt(bool force)
{
    const MqttTopicTree* tree = m_parts.live.mqttTopics;
    const auto info = tree->topicData().info(m_topic);
    if (!info) {
        m_title->setText(tr("<b>%1</b>: a level of the topic tree; select a topic below it.")
                             .arg(m_topic.toHtmlEscaped()));
        showNoFields(tr("(no messages on this level itself)"));
        return;
    }
    if (!force && info->messages == m_shownMessages)
        return;
    m_shownMessages = info->messages;
    QString title = u"<b>%1</b><br>"_s.arg(m_topic.toHtmlEscaped())
        + tr("%1 messages, %2, last %3, QoS %4%5")
              .arg(info->messages)
              .arg(sizeText(qint64(info->bytes)))
              .arg(sizeText(info->lastSize))
              .arg(info->qos)
              .arg(info->retained ? tr(", retained") : QString());
    if (info->rosType) {
        const bool ros2 = info->rosType->dialect == RosTypeRegistry::Dialect::Ros2;
        title += u"<br>"_s
            + (ros2 ? tr("ROS 2 type %1 (announced by mqtt_client)%2")
                    : tr("ROS type %1 (announced by mqtt_client)%2"))
                  .arg(info->rosType->name.toHtmlEscaped(),
                       info->rosType->stamped ? tr(", stamped") : QString());
        if (info->latencySamples)
            title += u"<br>"_s
                + tr("one-way latency %1 ms (mean of the last %2: %3 ms); valid only as far as the "
                     "sender's clock agrees with this one")
                      .arg(info->lastLatencyMs, 0, 'f', 1)
                      .arg(std::min<quint64>(info->latencySamples, 100))
                      .arg(info->meanLatencyMs, 0, 'f', 1);
    }
    if (info->malformedPayloads)
        title += u"<br><font color=\"#b00020\">"_s
            + tr("%1 payloads did not decode as the announced type").arg(info->malformedPayloads)
            + u"</font>"_s;
    if (!info->typeError.isEmpty())
        title += u"<br><font color=\"#b00020\">"_s
            + tr("malformed type announcement: %1").arg(info->typeError.toHtmlEscaped()) + u"</font>"_s;
    m_title->setText(title);

    const auto* history = tree->topicData().history(m_topic);
    m_lastPayload = history && !history->empty() ? history->back().payload : QByteArray();
    showPayload(m_lastPayload);

    // Fields: the decoded ROS message when mqtt_client announced the type, else JSON if it is.
    if (const auto registry = tree->topicData().registryFor(m_topic); registry && info->rosType) {
        RosDecodeLimits limits;
        limits.maxArrayElements = 32;
        if (const Result<RosValue> value = SourceMessage::decode(
                *registry, {SourceGraph::Mqtt, info->rosType->name, info->rosType}, m_lastPayload, limits);
            value)
            showFields(*value);
        else
            showNoFields(tr("does not decode as %1: %2").arg(info->rosType->name, value.error().toString()));
    } else if (!info->typeNote.isEmpty()) {
        showNoFields(info->typeNote);
    } else if (m_lastPayload.size() <= kMaxJsonFieldsBytes
               && !QJsonDocument::fromJson(m_lastPayload).isNull()) {
        showJsonFields(m_lastPayload);
    } else {
        showNoFields(tr("(no structure known: see Payload)"));
    }

    if (history) {
        const int n = int(history->size());
        m_history->setRowCount(n);
        for (int i = 0; i < n; ++i) {
            const MqttTopicTree::HistoryEntry& e = (*history)[size_t(n - 1 - i)];
            m_history->setItem(
                i, 0,
                new QTableWidgetItem(
                    QDateTime::fromMSecsSinceEpoch(e.receivedNs / 1000000).toString(u"HH:mm:ss.zzz"_s)));
            m_history->setItem(i, 1, new QTableWidgetItem(sizeText(e.payload.size())));
            m_history->setItem(i, 2, new QTableWidgetItem(e.retained ? tr("retained") : QString()));
        }
    }
    m_rate->setSamples(info->rateHistory, tr("msg/s"));
}

void DetailPane::refreshRos(bool force)
{
    const bool ros2 = m_kind == Kind::Ros2;
    const TopicTableModel* model = ros2 ? m_parts.ros2Topics : m_parts.live.rosTopics;
    const TopicInfo* t = model->graph().topic(m_topic);
    const TopicStats* s = model->stats(m_topic);
    const qint64 now = QDateTime::currentMSecsSinceEpoch() * 1000000LL;
    if (s && now - m_lastRosSample >= 1000000000LL) {
        m_lastRosSample = now;
        m_rosRates.append(s->rateHz);
        while (m_rosRates.size() > 120)
            m_rosRates.removeFirst();
        m_rate->setSamples(m_rosRates, tr("Hz"));
    }
    const quint64 messages = s ? s->messages : 0;
    if (!force && messages == m_shownMessages)
        return;
    m_shownMessages = messages;
    QString title = u"<b>%1</b>"_s.arg(m_topic.toHtmlEscaped());
    if (const QString endpoints = ros2 ? m_parts.graphs->ros2EndpointsText(m_topic) : QString();
        !endpoints.isEmpty()) {
        title += u"<br>"_s + endpoints.toHtmlEscaped(); // ROS 2: each endpoint's node and QoS
    } else if (t) {
        title += u"<br>"_s
            + tr("%1; publishers: %2; subscribers: %3")
                  .arg(t->type.toHtmlEscaped(), t->publishers.join(u", "_s).toHtmlEscaped(),
                       t->subscribers.join(u", "_s).toHtmlEscaped());
    }
    if (!s) {
        title += u"<br>"_s + tr("Check Monitor to subscribe and see its messages.");
        m_title->setText(title);
        showNoFields(tr("(not monitored)"));
        m_lastPayload.clear();
        showPayload(m_lastPayload);
        return;
    }
    title += u"<br>"_s
        + tr("%1 messages, %2 Hz, %3/s, last %4")
              .arg(s->messages)
              .arg(s->rateHz, 0, 'f', 2)
              .arg(sizeText(qint64(s->bytesPerSecond)), sizeText(s->lastSize));
    // ROS 2: samples DDS knows were sent and never came (a full receive buffer, a lossy link)
    if (s->lost)
        title += u", "_s + tr("%1 lost").arg(s->lost);
    // ROS 2, Header or not: the age its DDS source timestamp gives (rqt and ros2 topic give none
    // without a Header)
    if (std::isfinite(s->ageMs))
        title += u"<br>"_s
            + tr("%1 ms old when it came (median of the last %2, by the DDS source timestamp: the "
                 "writer's clock, true as far as it agrees with this one)")
                  .arg(s->ageMs, 0, 'f', 2)
                  .arg(TopicFigures::kAgeSamples);
    m_title->setText(title);
    m_lastPayload = s->lastMessage;
    showPayload(m_lastPayload);
    if (s->messages == 0) {
        showNoFields(tr("(waiting for the first message)"));
        return;
    }
    RosDecodeLimits limits;
    limits.maxArrayElements = 32;
    if (ros2) {
        const RosTypeRegistry& types = m_parts.live.ros2Types();
        if (!types.contains(s->type))
            showNoFields(tr("No ROS 2 definition of %1 is known: the payload shows its %n byte(s) raw.",
                            nullptr, s->lastSize)
                             .arg(s->type));
        else if (const Result<RosValue> value
                 = SourceMessage::decode(types, {SourceGraph::Ros2, s->type, {}}, s->lastMessage, limits);
                 value)
            showFields(*value);
        else
            showNoFields(value.error().toString());
        return;
    }
    RosTypeRegistry registry;
    if (const Result<void> added = registry.addDefinition(s->type, s->definition); !added) {
        showNoFields(added.error().toString());
    } else if (const Result<RosValue> value
               = SourceMessage::decode(registry, {SourceGraph::Ros1, s->type, {}}, s->lastMessage, limits);
               value) {
        showFields(*value);
    } else {
        showNoFields(value.error().toString());
    }
}

void DetailPane::refreshBroker()
{
    const QHash<QString, QString>& stats = m_parts.live.mqttTopics->topicData().store().statistics();
    QStringList keys = stats.keys();
    keys.sort();
    m_broker->setRowCount(int(keys.size()));
    for (int i = 0; i < keys.size(); ++i) {
        m_broker->setItem(i, 0, new QTableWidgetItem(keys[i]));
        m_broker->setItem(i, 1, new QTableWidgetItem(stats.value(keys[i])));
    }
    if (keys.isEmpty()) {
        m_broker->setRowCount(1);
        m_broker->setItem(
            0, 0,
            new QTableWidgetItem(tr("Turn on $SYS in the connection profile to see the broker's figures.")));
    }
}
