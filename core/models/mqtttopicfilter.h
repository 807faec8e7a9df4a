// SPDX-License-Identifier: MIT
#pragma once

#include <QSortFilterProxyModel>

/// Filters the topic tree by name (any level of the path) and, optionally, by the text of the
/// last payload; parents of a match stay visible.
class MqttTopicFilter : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    explicit MqttTopicFilter(QObject* parent = nullptr);

    void setText(const QString& text);
    QString text() const { return m_text; }
    void setSearchPayloads(bool on);
    bool searchPayloads() const { return m_payloads; }

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const override;

private:
    QString m_text;
    bool m_payloads = false;
};
