// Store work for a window, off its thread: `work` runs on the window's
// StoreWorker (its one connection), and `done` gets the result back on the
// GUI thread, or `failed` the message. Both are dropped when `context` is
// gone by then, so a closed window is never called back. The results travel
// through the application object, which outlives every window; `context` is
// only looked at on the GUI thread, where it is deleted.
#pragma once

#include "core/storage/SessionSource.h"
#include "core/storage/StoreWorker.h"

#include <QCoreApplication>
#include <QMetaObject>
#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>
#include <string>
#include <type_traits>
#include <utility>

namespace tactiscope::ui {

namespace detail {
template <typename Call>
void onGuiThread(QPointer<QObject> context, Call call)
{
    QMetaObject::invokeMethod(
        QCoreApplication::instance(),
        [context = std::move(context), call = std::move(call)]() mutable {
            if (context) call();
        },
        Qt::QueuedConnection);
}
}  // namespace detail

template <typename Work, typename Done>
void runOnStore(core::storage::StoreWorker& worker, QObject* context, Work work, Done done,
                std::function<void(const QString&)> failed)
{
    using Result = std::invoke_result_t<Work&, core::storage::SessionSource&>;
    const QPointer<QObject> guard(context);
    worker.post(
        [guard, work = std::move(work), done = std::move(done)](core::storage::SessionSource& store) mutable {
            if constexpr (std::is_void_v<Result>) {
                work(store);
                detail::onGuiThread(guard, std::move(done));
            } else {
                detail::onGuiThread(
                    guard, [done = std::move(done), result = work(store)]() mutable { done(std::move(result)); });
            }
        },
        [guard, failed = std::move(failed)](const std::string& error) {
            if (failed)
                detail::onGuiThread(guard, [failed, message = QString::fromStdString(error)] { failed(message); });
        });
}

}  // namespace tactiscope::ui
