#include "editor/MessagesPanel.h"

#include <QApplication>
#include <QStyle>

namespace throng::editor {

MessagesPanel::MessagesPanel(QWidget* parent) : QListWidget(parent)
{
    setObjectName("messagesPanel");
    setAlternatingRowColors(true);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    setWordWrap(true);
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    setToolTip(tr("What the last open or save reported, as file:line:column: message; "
                  "double-click a message to select its item"));
    connect(this, &QListWidget::itemActivated, this, [this](QListWidgetItem* row) {
        if (const std::optional<SceneItem> item = itemForKey(row->data(Qt::UserRole).toString().toStdString()))
            emit itemRequested(*item);
    });
}

QSize MessagesPanel::sizeHint() const
{
    return {480, 5 * fontMetrics().height()};
}

void MessagesPanel::showDiagnostics(const QString& headline, const std::vector<sim::Diagnostic>& diagnostics)
{
    showNote(headline);
    QStyle* style = QApplication::style();
    for (const sim::Diagnostic& d : diagnostics) {
        const bool error = d.severity == sim::Severity::Error;
        auto* item = new QListWidgetItem(
            style->standardIcon(error ? QStyle::SP_MessageBoxCritical : QStyle::SP_MessageBoxWarning),
            QString::fromStdString(d.format()), this);
        if (!d.key.empty()) {
            item->setToolTip(QString::fromStdString(d.key));
            item->setData(Qt::UserRole, QString::fromStdString(d.key));
        }
    }
}

void MessagesPanel::showNote(const QString& note)
{
    clear();
    addItem(new QListWidgetItem(QApplication::style()->standardIcon(QStyle::SP_MessageBoxInformation), note));
}

}  // namespace throng::editor
