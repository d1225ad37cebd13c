addSbtPlugin("com.eed3si9n"       % "sbt-assembly"        % "2.3.1")
addSbtPlugin("pl.project13.scala" % "sbt-jmh"             % "0.4.8")
addSbtPlugin("org.scalameta"      % "sbt-scalafmt"        % "2.6.2")
addSbtPlugin("com.github.sbt"     % "sbt-native-packager" % "1.11.4")

// The build's own step after assembly (project/PlainLambdas.scala) reads and writes class files.
libraryDependencies += "org.ow2.asm" % "asm" % "9.6"
