package tracer.io

import java.io.IOException
import java.nio.charset.MalformedInputException
import java.nio.file.{AccessDeniedException, FileSystemException, NoSuchFileException}

/** The plain reasons of [[IoFailure]]: never a bare path, never empty. */
class IoFailureSuite extends munit.FunSuite:

  test("each kind of failure has its plain reason, not the path the JDK puts in its message"):
    assertEquals(IoFailure.reason(NoSuchFileException("/a/b")), "no such file")
    assertEquals(IoFailure.reason(AccessDeniedException("/proc/1/mem")), "permission denied")
    assertEquals(IoFailure.reason(MalformedInputException(1)), "not UTF-8 text")
    assertEquals(
      IoFailure.reason(FileSystemException("/x", "", "Is a directory")),
      "Is a directory"
    )
    assertEquals(IoFailure.reason(FileSystemException("/x")), "FileSystemException")

  test("another failure gives its message, or its name when it has none"):
    assertEquals(IoFailure.reason(IOException("Stream closed")), "Stream closed")
    assertEquals(IoFailure.reason(IOException()), "IOException")
    assertEquals(IoFailure.reason(IOException("")), "IOException")
